// Bad input never crashes and never moves the DSV's state machine where the manual says it must
// not; each refusal carries the manual's (or CiA 301's) abort code.
#include <random>

#include "tests/devices/dsv/dsv_fixture.h"

namespace dsvtest {

TEST_F(DsvTest, ObjectsOfOtherModesDoNotExistForTheBus) {
  // Mode 1: 6380h, 2200h (controller), 1A01h sub 2 of mode 4 … answer 0x06020000, whatever the access.
  EXPECT_EQ(sdo({0x40, 0x80, 0x63, 0x01}), Frames{resp({0x80, 0x80, 0x63, 0x01, 0x00, 0x00, 0x02, 0x06})});
  EXPECT_EQ(sdo({0x2B, 0x80, 0x63, 0x01, 0x00, 0x10}), Frames{resp({0x80, 0x80, 0x63, 0x01, 0x00, 0x00, 0x02, 0x06})});
  EXPECT_EQ(sdo({0x23, 0x81, 0x63, 0x01, 0x00, 0x10}), Frames{resp({0x80, 0x81, 0x63, 0x01, 0x00, 0x00, 0x02, 0x06})});
  EXPECT_EQ(read_abort(0x2200), 0x06020000u);
  EXPECT_EQ(read_abort(0x1402, 0), 0x06020000u);  // only two PDOs each way
  EXPECT_EQ(read_abort(0x1802, 0), 0x06020000u);
  EXPECT_EQ(read_abort(0x1200, 0), 0x06020000u);
  // The option keeps every object visible.
  make(bus_mode({{"objects_follow_mode", "false"}}));
  EXPECT_EQ(read(0x6380, 1), 0);
}

TEST_F(DsvTest, ControlModeValues) {
  EXPECT_EQ(write(0x6043, 0, 2, 1), 0x06040043u);   // gap
  EXPECT_EQ(write(0x6043, 0, 4, 1), 0x06040043u);   // controller mode on the amplifier
  EXPECT_EQ(write(0x6043, 0, 10, 1), 0x06090031u);
  EXPECT_EQ(write(0x6043, 0, 0xFF, 1), 0x06090032u);
  make(bus_mode({{"control_mode", "0"}}), "controller");
  EXPECT_EQ(write(0x6043, 0, 1, 1), 0x06040043u);   // amplifier mode on the controller
  EXPECT_EQ(write(0x6043, 0, 6, 1), 0u);
}

TEST_F(DsvTest, EnumerationsAndRanges) {
  EXPECT_EQ(write(0x6330, 0, 1, 1), 0x06040043u);  // ramp type 0 or 3
  EXPECT_EQ(write(0x6330, 0, 4, 1), 0x06090031u);
  EXPECT_EQ(write(0x62F0, 0, 2, 1), 0x06090031u);
  EXPECT_EQ(write(0x6332, 1, 51001, 2), 0x06090031u);
  EXPECT_EQ(write(0x6345, 1, 16385, 2), 0x06090031u);
  EXPECT_EQ(write(0x6362, 1, 19, 2), 0x06090032u);
  EXPECT_EQ(write(0x2043, 0, 4, 1), 0x06090031u);
  EXPECT_EQ(write(0x2042, 0, 4, 1), 0x06090031u);
  make(bus_mode({{"control_mode", "9"}}), "controller");
  EXPECT_EQ(write(0x2200, 0, 1, 1), 0x06040043u);
  EXPECT_EQ(write(0x2202, 0, 3, 1), 0x06040043u);   // "–" in mode 9
  EXPECT_EQ(write(0x6202, 0, 5, 1), 0x06040043u);
  EXPECT_EQ(write(0x6202, 0, 68, 1), 0x06090031u);
  EXPECT_EQ(write(0x6201, 0, 3, 1), 0x06090031u);
  EXPECT_EQ(write(0x6670, 0, 1, 1), 0x06040043u);   // window type 0 or 2
  EXPECT_EQ(write(0x6231, 1, 2000001, 4), 0x06090031u);  // mm: 0..2000000
  EXPECT_EQ(write(0x6234, 1, 10001, 4), 0x06090031u);    // voltage interface 0..10000 mV
  ASSERT_EQ(write(0x2200, 0, 2, 1), 0u);
  EXPECT_EQ(write(0x6234, 1, 20000, 4), 0u);             // current interface 0..20000 µA
  EXPECT_EQ(write(0x6600, 1, 1, 4), 0x06090031u);        // set point above max reference (0)
  ASSERT_EQ(write(0x6231, 1, 100000, 4), 0u);
  EXPECT_EQ(write(0x6600, 1, 100000, 4), 0u);
  EXPECT_EQ(write(0x6600, 1, 0xFFFFFFFF, 4), 0x06090032u);
  EXPECT_EQ(write(0x6603, 1, 25001, 4), 0x06090031u);
}

TEST_F(DsvTest, RpdoValuesAreLimitedNotRefused) {
  make(bus_mode({{"control_mode", "4"}}), "controller");
  start();
  h->send(0x201, {0x07, 0x00, 0x00, 0xF0});  // −4096 in mode 4: limited to 0
  h->take();
  EXPECT_EQ(read(0x6380, 1), 0);
  EXPECT_EQ(write(0x6380, 1, 0xF000, 2), 0x06090032u);
}

TEST_F(DsvTest, FixedMappingAndReadOnlyCobIds) {
  EXPECT_EQ(read(0x1600, 0), 2);
  EXPECT_EQ(read(0x1600, 2), 0x63000110);
  EXPECT_EQ(read(0x1601, 0), 3);
  EXPECT_EQ(read(0x1601, 3), 0x6B000110);
  EXPECT_EQ(read(0x1A01, 0), 0);
  EXPECT_EQ(write(0x1600, 0, 0, 1), 0x06010000u);
  EXPECT_EQ(write(0x1600, 1, 0x60400010, 4), 0x06010000u);
  EXPECT_EQ(write(0x1800, 1, 0x80000181, 4), 0x06010000u);
  EXPECT_EQ(write(0x1800, 2, 254, 1), 0u);
  EXPECT_EQ(write(0x1400, 2, 254, 1), 0x06040043u);
  make(bus_mode({{"pdo_cobid_writable", "true"}}));
  EXPECT_EQ(write(0x1800, 1, 0x80000181, 4), 0u);
  start();
  h->send(0x201, {0x07, 0x00, 0x00, 0x00});
  EXPECT_TRUE(h->take().empty());  // TPDO1 now invalid
}

TEST_F(DsvTest, WrongPdoLengthsAndInactivePdos) {
  start();
  h->send(0x201, {0x07, 0x00, 0x00});  // 3 of 4 bytes: ignored
  h->send(0x301, {0x07, 0x00, 0x00, 0x20, 0x00, 0x10});  // RPDO2 inactive in op-mode 2
  h->send(0x401, {0x07, 0x00});          // no RPDO3
  EXPECT_TRUE(h->take().empty());
  EXPECT_EQ(status(), 0x0008);
  h->send(Frame::remote(0x281, 2));  // TPDO2 inactive in mode 1
  EXPECT_TRUE(h->take().empty());
  h->send(0x201, {0x07, 0x00, 0x00, 0x20, 0x99, 0x99, 0x99, 0x99});
  EXPECT_EQ(h->take(), Frames{Frame(0x181, {0x0F, 0x00})});
}

TEST_F(DsvTest, WritesInTheWrongStateOrUnderLocalControl) {
  ASSERT_EQ(write(0x6040, 0, 0x0003, 2), 0u);
  EXPECT_EQ(write(0x6043, 0, 3, 1), 0x08000022u);
  EXPECT_EQ(write(0x2042, 0, 1, 1), 0x08000022u);
  EXPECT_EQ(write(0x604F, 0, 1, 1), 0x08000022u);
  EXPECT_EQ(write(0x6332, 1, 100, 2), 0u);  // parameters: any state
  ASSERT_EQ(write(0x6040, 0, 0x0000, 2), 0u);
  ASSERT_EQ(write(0x604F, 0, 1, 1), 0u);
  EXPECT_EQ(write(0x6043, 0, 3, 1), 0x08000021u);  // local control before the device state
  EXPECT_EQ(write(0x2042, 0, 1, 1), 0x08000021u);
  EXPECT_EQ(write(0x6040, 0, 0x0007, 2), 0x08000021u);
  EXPECT_EQ(write(0x6332, 1, 200, 2), 0u);  // parameterisation stays possible
  make(bus_mode({{"local_strict", "true"}, {"device_local", "1"}}));
  EXPECT_EQ(write(0x6332, 1, 200, 2), 0x08000021u);
  EXPECT_EQ(write(0x1017, 0, 100, 2), 0x08000021u);
  EXPECT_EQ(write(0x604F, 0, 0, 1), 0u);
  EXPECT_EQ(write(0x6332, 1, 200, 2), 0u);
}

TEST_F(DsvTest, MeasuredValuesPrintedReadWrite) {
  make(bus_mode({{"control_mode", "4"}}), "controller");
  EXPECT_EQ(write(0x6381, 1, 1234, 2), 0u);  // accepted …
  EXPECT_EQ(read(0x6381, 1), 0);              // … and overwritten by the measurement
  make(bus_mode({{"control_mode", "4"}, {"actual_value_writable", "false"}}), "controller");
  EXPECT_EQ(write(0x6381, 1, 1234, 2), 0x06010000u);
}

TEST_F(DsvTest, MemoryFailureAndResolutionFailure) {
  dev->inject_fault("memory_failure", true);
  EXPECT_EQ(sdo({0x23, 0x10, 0x10, 0x01, 0x73, 0x61, 0x76, 0x65}),
            (Frames{Frame(0x081, {0x20, 0x55, 0x01, 0, 0, 0, 0, 0}), resp({0x80, 0x10, 0x10, 0x01, 0x00, 0x00, 0x06, 0x06})}));
  EXPECT_EQ(status(), 0x0001);
  dev->inject_fault("memory_failure", false);
  make();
  dev->inject_fault("resolution_update_failure", true);
  h->run_ms(1);
  EXPECT_EQ(h->take(), Frames{Frame(0x081, {0x10, 0x55, 0x01, 0, 0, 0, 0, 0})});
  dev->inject_fault("over_current", true);
  h->run_ms(1);
  EXPECT_EQ(h->take(), Frames{Frame(0x081, {0x00, 0x23, 0x03, 0, 0, 0, 0, 0})});
}

TEST_F(DsvTest, RandomFramesNeverCrashAndTheNodeKeepsAnswering) {
  make(bus_mode({{"control_mode", "9"}}), "controller");
  std::mt19937 rng(4081);
  const std::uint32_t ids[] = {0x000, 0x080, 0x181, 0x201, 0x281, 0x301, 0x601, 0x701, 0x100};
  for (int i = 0; i < 20000; ++i) {
    Frame f;
    f.id = ids[rng() % std::size(ids)];
    const auto dlc = rng() % 9;
    if (rng() % 16 == 0) {
      f = Frame::remote(f.id, static_cast<std::uint8_t>(dlc));
    } else {
      for (unsigned b = 0; b < dlc; ++b) f.data.push_back(static_cast<std::uint8_t>(rng()));
    }
    if (f.id == 0x000 && f.data.size() == 2 && (f.data[0] == 0x81 || f.data[0] == 0x82 || f.data[0] == 0x02)) f.data[1] = 0x7F;
    if (f.id == 0x601 && f.data.size() == 8 && (f.data[0] & 0xE0) == 0x20 && f.data[1] == 0x00 && f.data[2] == 0x20) {
      continue;  // keep node-ID and bit rate
    }
    h->send(f);
    if (i % 100 == 0) h->run_ticks(1);
  }
  h->nmt(0x80, 1);
  h->take();
  EXPECT_EQ(sdo({0x40, 0x00, 0x10, 0x00}), Frames{resp({0x43, 0x00, 0x10, 0x00, 0x98, 0x01, 0x00, 0x00})});
}

// CiA 301 gives 0x06010002 for a write to a read-only object; the DSV manual's list of abort
// codes (§4.3.3) has only 0x06010000 (docs/devices/dsv.md, "Writing a read-only object").
TEST_F(DsvTest, WritingTheDeviceTypeAborts06010000) {
  const auto device_type = read(0x1000, 0);
  EXPECT_EQ(write(0x1000, 0, 0, 4), 0x06010000u);
  EXPECT_EQ(write(0x1001, 0, 0, 1), 0x06010000u);
  EXPECT_EQ(read(0x1000, 0), device_type);
}

}  // namespace dsvtest
