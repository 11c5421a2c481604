// The generic EDS node, frame level: the CiA 401-style fixture tests/data/eds/io_module.eds loaded
// as node 5 and driven by a scripted master in virtual time. Each test is one point of the
// foundation issue's "done when" list for `vplant node --eds`.
#include "devices/generic/eds_node.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <memory>
#include <string>

#include "devices/canopen/eds.h"
#include "tests/support/canopen_harness.h"
#include "tests/support/temp_path.h"

using vtest::Frame;
using vtest::Frames;

namespace {

const std::string kFixture = VPLANT_TEST_DATA_DIR "/eds/io_module.eds";
constexpr std::uint32_t kSave = 0x65766173, kLoad = 0x64616F6C;

Frame sdo_reply(std::initializer_list<std::uint8_t> bytes) { return Frame(0x585, bytes); }

// The abort frame for (index, sub, code), as the node must send it.
Frame abort_frame(std::uint16_t index, std::uint8_t sub, std::uint32_t code) {
  return Frame(0x585, {0x80, static_cast<std::uint8_t>(index), static_cast<std::uint8_t>(index >> 8), sub,
                       static_cast<std::uint8_t>(code), static_cast<std::uint8_t>(code >> 8),
                       static_cast<std::uint8_t>(code >> 16), static_cast<std::uint8_t>(code >> 24)});
}

class EdsNodeTest : public ::testing::Test {
 protected:
  void SetUp() override { boot(); }

  void boot(const std::string& store = {}) {
    h.reset();
    devices::DeviceOptions options;
    options.node_id = 5;
    options.store_path = store;
    std::string error;
    device = devices::EdsNode::load(kFixture, options, error);
    ASSERT_TRUE(device) << error;
    h = std::make_unique<vtest::CanopenHarness>(device->node());
    h->power_on();
  }

  // One SDO request (padded to 8 bytes); all frames the node answers with.
  Frames req(std::initializer_list<std::uint8_t> bytes) {
    std::vector<std::uint8_t> data(bytes);
    data.resize(8, 0);
    h->take();
    h->send(Frame(0x605, data));
    return h->take();
  }

  canopen::ObjectDictionary& od() { return device->node().od(); }

  std::unique_ptr<devices::EdsNode> device;
  std::unique_ptr<vtest::CanopenHarness> h;  // destroyed before the device it refers to
};

}  // namespace

TEST_F(EdsNodeTest, BootUpFrame) {
  boot();
  EXPECT_EQ(h->take(), Frames{Frame(0x705, {0x00})});
  EXPECT_EQ(device->node().nmt_state(), canopen::NmtState::PreOperational);
}

TEST_F(EdsNodeTest, EveryObjectReadsItsEdsDefaultSegmentedWhenLong) {
  h->take();
  int checked = 0, segmented = 0;
  for (const auto& [index, object] : od().objects()) {
    for (const auto& [sub, entry] : object.entries) {
      SCOPED_TRACE(::testing::Message() << std::hex << "0x" << index << " sub " << int(sub));
      std::uint32_t abort = 0;
      if (!entry.readable()) {
        EXPECT_FALSE(h->upload(index, sub, &abort));
        EXPECT_EQ(abort, 0x06010001u);  // write-only
        continue;
      }
      if (index == 0x1003 && sub >= 1) {
        EXPECT_FALSE(h->upload(index, sub, &abort));
        EXPECT_EQ(abort, 0x08000024u);  // no error recorded yet: no data
        continue;
      }
      const auto expected = entry.default_for_node(5);
      if (expected.size() > 4 || expected.empty()) {
        // The initiate answer announces a segmented transfer with the size.
        const auto first = req({0x40, static_cast<std::uint8_t>(index), static_cast<std::uint8_t>(index >> 8), sub});
        ASSERT_EQ(first.size(), 1u);
        EXPECT_EQ(first[0].data[0], 0x41);
        EXPECT_EQ(first[0].data[4], expected.size());
        ++segmented;
      }
      const auto value = h->upload(index, sub, &abort);
      ASSERT_TRUE(value) << "abort 0x" << abort;
      EXPECT_EQ(*value, expected);
      ++checked;
    }
  }
  std::size_t entries = 0;
  for (const auto& [index, object] : od().objects()) entries += object.entries.size();
  EXPECT_EQ(static_cast<std::size_t>(checked), entries - 1 - 4);  // all but 0x2003 (wo) and 0x1003 sub 1-4
  EXPECT_GE(segmented, 8);  // strings, 64-bit values, the octet string, the empty DOMAIN
}

TEST_F(EdsNodeTest, DefaultsOnTheWireAreTheFileText) {
  h->take();
  // 0x1000 = 0x000F0191, 0x1014 = $NODEID+0x80, 0x1401:1 = 0x300+$NODEID, 0x2000 = 010 (octal),
  // 0x2001 = -1000, 0x6200:2 from [6200Value], 0x0005 = dummy UNSIGNED8 (8 bits).
  EXPECT_EQ(req({0x40, 0x00, 0x10, 0x00}), Frames{sdo_reply({0x43, 0x00, 0x10, 0x00, 0x91, 0x01, 0x0F, 0x00})});
  EXPECT_EQ(req({0x40, 0x14, 0x10, 0x00}), Frames{sdo_reply({0x43, 0x14, 0x10, 0x00, 0x85, 0x00, 0x00, 0x00})});
  EXPECT_EQ(req({0x40, 0x01, 0x14, 0x01}), Frames{sdo_reply({0x43, 0x01, 0x14, 0x01, 0x05, 0x03, 0x00, 0x00})});
  EXPECT_EQ(req({0x40, 0x00, 0x20, 0x00}), Frames{sdo_reply({0x4F, 0x00, 0x20, 0x00, 0x08, 0x00, 0x00, 0x00})});
  EXPECT_EQ(req({0x40, 0x01, 0x20, 0x00}), Frames{sdo_reply({0x43, 0x01, 0x20, 0x00, 0x18, 0xFC, 0xFF, 0xFF})});
  EXPECT_EQ(req({0x40, 0x00, 0x62, 0x02}), Frames{sdo_reply({0x4F, 0x00, 0x62, 0x02, 0x5A, 0x00, 0x00, 0x00})});
  EXPECT_EQ(req({0x40, 0x05, 0x00, 0x00}), Frames{sdo_reply({0x43, 0x05, 0x00, 0x00, 0x08, 0x00, 0x00, 0x00})});
  // 0x1008 "vplant IO-16 test module": 24 bytes in four segments.
  EXPECT_EQ(req({0x40, 0x08, 0x10, 0x00}), Frames{sdo_reply({0x41, 0x08, 0x10, 0x00, 24, 0, 0, 0})});
  EXPECT_EQ(req({0x60}), Frames{sdo_reply({0x00, 'v', 'p', 'l', 'a', 'n', 't', ' '})});
  EXPECT_EQ(req({0x70}), Frames{sdo_reply({0x10, 'I', 'O', '-', '1', '6', ' ', 't'})});
  EXPECT_EQ(req({0x60}), Frames{sdo_reply({0x00, 'e', 's', 't', ' ', 'm', 'o', 'd'})});
  EXPECT_EQ(req({0x70}), Frames{sdo_reply({0x19, 'u', 'l', 'e', 0, 0, 0, 0})});  // 3 bytes, last
}

// ---- every abort code of the list, each from the request that should produce it ----------

TEST_F(EdsNodeTest, SdoProtocolAborts) {
  // 0x05030000: the second segment request repeats toggle 0.
  req({0x40, 0x08, 0x10, 0x00});
  req({0x60});
  EXPECT_EQ(req({0x60}), Frames{abort_frame(0x1008, 0, 0x05030000)});
  // 0x05040000: a segmented upload left idle for the SDO timeout (1 s).
  req({0x40, 0x08, 0x10, 0x00});
  h->run_ms(999);
  EXPECT_TRUE(h->take().empty());
  h->run_ms(2);
  EXPECT_EQ(h->take(), Frames{abort_frame(0x1008, 0, 0x05040000)});
  // 0x05040001: command specifier 7, and block download (not supported).
  EXPECT_EQ(req({0xE0, 0x00, 0x10, 0x00}), Frames{abort_frame(0x1000, 0, 0x05040001)});
  EXPECT_EQ(req({0xC6, 0x02, 0x20, 0x00, 0x10, 0, 0, 0}), Frames{abort_frame(0x2002, 0, 0x05040001)});
}

TEST_F(EdsNodeTest, AccessAborts) {
  // 0x06010000: a download to a data type entry (Dummy0005=1 declares 0x0005).
  EXPECT_EQ(req({0x2F, 0x05, 0x00, 0x00, 0x10, 0, 0, 0}), Frames{abort_frame(0x0005, 0, 0x06010000)});
  // 0x06010001: upload of the write-only command word.
  EXPECT_EQ(req({0x40, 0x03, 0x20, 0x00}), Frames{abort_frame(0x2003, 0, 0x06010001)});
  // 0x06010002: download to the read-only device type, and to a const string.
  EXPECT_EQ(req({0x23, 0x00, 0x10, 0x00, 1, 2, 3, 4}), Frames{abort_frame(0x1000, 0, 0x06010002)});
  EXPECT_EQ(req({0x21, 0x08, 0x10, 0x00, 3, 0, 0, 0}), Frames{abort_frame(0x1008, 0, 0x06010002)});
  // 0x06020000 / 0x06090011: no such object / sub-index.
  EXPECT_EQ(req({0x40, 0x00, 0x30, 0x00}), Frames{abort_frame(0x3000, 0, 0x06020000)});
  EXPECT_EQ(req({0x40, 0x18, 0x10, 0x07}), Frames{abort_frame(0x1018, 7, 0x06090011)});
}

TEST_F(EdsNodeTest, PdoMappingAborts) {
  // 0x08000022: the mapping of a valid TPDO cannot change.
  EXPECT_EQ(req({0x2F, 0x00, 0x1A, 0x00, 0x00, 0, 0, 0}), Frames{abort_frame(0x1A00, 0, 0x08000022)});
  // CiA 301 procedure: invalidate, clear sub 0, then write entries.
  EXPECT_EQ(h->write(0x1800, 1, 0x80000185u, 4), 0u);
  EXPECT_EQ(h->write(0x1A00, 0, 0, 1), 0u);
  // 0x06040041: 0x2000 has PDOMapping=0.
  EXPECT_EQ(req({0x23, 0x00, 0x1A, 0x01, 0x08, 0x00, 0x00, 0x20}), Frames{abort_frame(0x1A00, 1, 0x06040041)});
  // 0x06040042: 32 + 32 + 16 bits do not fit in 8 bytes.
  EXPECT_EQ(h->write(0x1A00, 1, 0x20010020u, 4), 0u);
  EXPECT_EQ(h->write(0x1A00, 2, 0x20010020u, 4), 0u);
  EXPECT_EQ(h->write(0x1A00, 3, 0x64010110u, 4), 0u);
  EXPECT_EQ(req({0x2F, 0x00, 0x1A, 0x00, 0x03, 0, 0, 0}), Frames{abort_frame(0x1A00, 0, 0x06040042)});
  EXPECT_EQ(h->write(0x1A00, 0, 2, 1), 0u);  // two fit
}

TEST_F(EdsNodeTest, ParameterAborts) {
  // 0x06040043: a second consumer heartbeat time for node 0x20.
  EXPECT_EQ(h->write(0x1016, 1, (0x20u << 16) | 150u, 4), 0u);
  EXPECT_EQ(req({0x23, 0x16, 0x10, 0x02, 0xC8, 0x00, 0x20, 0x00}), Frames{abort_frame(0x1016, 2, 0x06040043)});
  // 0x06070010: segmented download announcing 4 bytes, delivering 5.
  EXPECT_EQ(req({0x21, 0x01, 0x20, 0x00, 4, 0, 0, 0}), Frames{sdo_reply({0x60, 0x01, 0x20, 0x00, 0, 0, 0, 0})});
  EXPECT_EQ(req({0x05, 1, 2, 3, 4, 5, 0, 0}), Frames{abort_frame(0x2001, 0, 0x06070010)});
  // 0x06070012 / 0x06070013: 4 bytes and 1 byte for the UNSIGNED16 heartbeat time.
  EXPECT_EQ(req({0x23, 0x17, 0x10, 0x00, 1, 0, 0, 0}), Frames{abort_frame(0x1017, 0, 0x06070012)});
  EXPECT_EQ(req({0x2F, 0x17, 0x10, 0x00, 1, 0, 0, 0}), Frames{abort_frame(0x1017, 0, 0x06070013)});
  // 0x06090030: transmission type 241 is reserved; sub 0 of 0x1003 only accepts 0.
  EXPECT_EQ(req({0x2F, 0x00, 0x18, 0x02, 241, 0, 0, 0}), Frames{abort_frame(0x1800, 2, 0x06090030)});
  EXPECT_EQ(req({0x2F, 0x03, 0x10, 0x00, 1, 0, 0, 0}), Frames{abort_frame(0x1003, 0, 0x06090030)});
  // 0x06090031 / 0x06090032: 0x2000 has LowLimit=1, HighLimit=200.
  EXPECT_EQ(req({0x2F, 0x00, 0x20, 0x00, 201, 0, 0, 0}), Frames{abort_frame(0x2000, 0, 0x06090031)});
  EXPECT_EQ(req({0x2F, 0x00, 0x20, 0x00, 0, 0, 0, 0}), Frames{abort_frame(0x2000, 0, 0x06090032)});
  EXPECT_EQ(h->write(0x2000, 0, 200, 1), 0u);
}

TEST_F(EdsNodeTest, DeviceAborts) {
  // 0x08000020: "store parameters" with a wrong signature.
  EXPECT_EQ(req({0x23, 0x10, 0x10, 0x01, 's', 'a', 'v', 'x'}), Frames{abort_frame(0x1010, 1, 0x08000020)});
  // 0x08000021: the device is operated locally (operator fault "local_control").
  ASSERT_EQ(device->inject_fault("local_control", true), "");
  EXPECT_EQ(req({0x2F, 0x00, 0x20, 0x00, 5, 0, 0, 0}), Frames{abort_frame(0x2000, 0, 0x08000021)});
  EXPECT_EQ(h->read_u(0x2000, 0), 8u);              // reading stays possible
  EXPECT_EQ(h->write(0x1017, 0, 100, 2), 0u);        // the communication area stays configurable
  ASSERT_EQ(device->inject_fault("local_control", false), "");
  EXPECT_EQ(h->write(0x2000, 0, 5, 1), 0u);
  // 0x08000000: a general device fault (operator fault "internal_fault") on application objects.
  ASSERT_EQ(device->inject_fault("internal_fault", true), "");
  EXPECT_EQ(req({0x40, 0x00, 0x20, 0x00}), Frames{abort_frame(0x2000, 0, 0x08000000)});
  EXPECT_EQ(req({0x2F, 0x00, 0x20, 0x00, 6, 0, 0, 0}), Frames{abort_frame(0x2000, 0, 0x08000000)});
  ASSERT_EQ(device->inject_fault("internal_fault", false), "");
  EXPECT_EQ(h->read_u(0x2000, 0), 5u);
  EXPECT_NE(device->inject_fault("no_such_fault", true), "");
}

// ---- error control, NMT, PDOs -----------------------------------------------------------------------

TEST_F(EdsNodeTest, HeartbeatAtTheProducerTimePeriod) {
  h->take();
  h->run_ms(500);
  EXPECT_TRUE(h->take().empty());  // 0x1017 = 0 in the file: no heartbeat
  ASSERT_EQ(h->write(0x1017, 0, 100, 2), 0u);
  h->take();
  const auto start = h->now();
  h->run_ms(1001);
  const auto frames = h->take_times();
  ASSERT_EQ(frames.size(), 10u);
  for (std::size_t i = 0; i < frames.size(); ++i) EXPECT_EQ(frames[i] - start, sim::milliseconds(100 * static_cast<int>(i + 1)));
  h->run_ms(100);
  EXPECT_EQ(h->take(), Frames{Frame(0x705, {0x7F})});  // pre-operational, 1100 ms
  ASSERT_EQ(h->write(0x1017, 0, 250, 2), 0u);
  h->take();
  h->run_ms(249);
  EXPECT_TRUE(h->take().empty());
  h->run_ms(2);  // the new period counts from the write
  EXPECT_EQ(h->take(), Frames{Frame(0x705, {0x7F})});
}

TEST_F(EdsNodeTest, NmtStatesAndTheServicesThatRunInThem) {
  ASSERT_EQ(h->write(0x1017, 0, 100, 2), 0u);
  od().set<std::uint8_t>(0x6000, 1, 0x12);
  h->run_ms(1);  // each 100 ms window below then holds exactly one heartbeat
  h->take();
  auto heartbeat_and_sync = [&] {
    h->run_ms(100);
    h->send(0x080, {});
    return h->take();
  };
  // Pre-operational: SDO and heartbeat, no PDOs.
  EXPECT_EQ(heartbeat_and_sync(), Frames{Frame(0x705, {0x7F})});
  // Start (addressed): PDOs run.
  h->nmt(0x01, 5);
  EXPECT_EQ(device->node().nmt_state(), canopen::NmtState::Operational);
  const Frames operational = heartbeat_and_sync();
  ASSERT_EQ(operational.size(), 2u);
  EXPECT_EQ(operational[0], Frame(0x705, {0x05}));
  EXPECT_EQ(operational[1].id, 0x185u);
  // Stop (broadcast): heartbeat only; SDO and PDOs silent.
  h->nmt(0x02, 0);
  EXPECT_EQ(heartbeat_and_sync(), Frames{Frame(0x705, {0x04})});
  EXPECT_TRUE(req({0x40, 0x00, 0x10, 0x00}).empty());
  // A command for another node changes nothing.
  h->nmt(0x01, 6);
  EXPECT_EQ(device->node().nmt_state(), canopen::NmtState::Stopped);
  // Enter pre-operational: SDO again, still no PDOs.
  h->nmt(0x80, 5);
  EXPECT_EQ(heartbeat_and_sync(), Frames{Frame(0x705, {0x7F})});
  EXPECT_EQ(req({0x40, 0x00, 0x10, 0x00}).size(), 1u);
  // Reset application: boot-up, application and communication areas back to their defaults.
  ASSERT_EQ(h->write(0x2000, 0, 42, 1), 0u);
  h->nmt(0x81, 5);
  h->run_ticks(1);
  EXPECT_EQ(h->take(), Frames{Frame(0x705, {0x00})});
  EXPECT_EQ(h->read_u(0x2000, 0), 8u);
  EXPECT_EQ(h->read_u(0x1017, 0), 0u);
  // Reset communication: boot-up; the application area keeps its values.
  ASSERT_EQ(h->write(0x2000, 0, 42, 1), 0u);
  ASSERT_EQ(h->write(0x1017, 0, 100, 2), 0u);
  h->nmt(0x82, 0);
  h->run_ticks(1);
  EXPECT_EQ(h->take(), Frames{Frame(0x705, {0x00})});
  EXPECT_EQ(h->read_u(0x2000, 0), 42u);
  EXPECT_EQ(h->read_u(0x1017, 0), 0u);
}

// The generic node's NMT machine in its own transition log (CiA 301 names, the command and its
// sender as the cause) and in its machines (OFF only while unpowered).
TEST_F(EdsNodeTest, NmtMachineRecordsEachTransitionWithItsCause) {
  const auto nmt_entries = [&](std::uint64_t after) {
    std::vector<devices::Transition> out;
    device->transition_log().for_each_after(after, [&](const devices::Transition& t) {
      EXPECT_EQ(t.machine, "nmt");  // its only machine
      out.push_back(t);
    });
    return out;
  };
  const auto boot = nmt_entries(0);
  ASSERT_EQ(boot.size(), 2u);
  EXPECT_EQ(boot[0].from, "OFF");
  EXPECT_EQ(boot[0].to, "INITIALISING");
  EXPECT_EQ(boot[0].cause, devices::TransitionCause::Boot);
  EXPECT_EQ(boot[1].transition, "boot-up");
  EXPECT_EQ(boot[1].to, "PRE-OPERATIONAL");
  const auto seq = device->transition_log().last_seq();
  h->nmt(0x01, 5);
  h->nmt(0x02, 0);
  h->nmt(0x81, 5);
  h->run_ticks(1);
  const auto t = nmt_entries(seq);
  ASSERT_EQ(t.size(), 4u);
  EXPECT_EQ(t[0].transition, "NMT 01h");
  EXPECT_EQ(t[0].to, "OPERATIONAL");
  EXPECT_EQ(t[0].cause, devices::TransitionCause::NmtCommand);
  EXPECT_EQ(t[0].detail, "the master");
  EXPECT_EQ(t[1].transition, "NMT 02h");
  EXPECT_EQ(t[1].from, "OPERATIONAL");
  EXPECT_EQ(t[1].to, "STOPPED");
  EXPECT_EQ(t[2].transition, "NMT 81h");
  EXPECT_EQ(t[2].to, "INITIALISING");
  EXPECT_EQ(t[3].transition, "boot-up");
  EXPECT_EQ(t[3].cause, devices::TransitionCause::NmtCommand);
  EXPECT_EQ(t[3].value, 0x81u);
  auto machines = device->machines();
  ASSERT_EQ(machines.size(), 1u);
  EXPECT_EQ(machines[0].state, "PRE-OPERATIONAL");
  device->power_off();
  machines = device->machines();
  EXPECT_EQ(machines[0].state, "OFF");
  const auto off = nmt_entries(seq + 4);
  ASSERT_EQ(off.size(), 1u);
  EXPECT_EQ(off[0].to, "OFF");
  EXPECT_EQ(off[0].cause, devices::TransitionCause::Power);
}

TEST_F(EdsNodeTest, TpdosGoOutOnSyncPerTheirTransmissionType) {
  od().set<std::uint8_t>(0x6000, 1, 0x12);
  od().set<std::uint8_t>(0x6000, 2, 0x34);
  od().set<std::int16_t>(0x6401, 1, -2);
  h->nmt(0x01, 5);
  h->take();
  // TPDO1 (type 1): 6000:1, 6000:2, 6401:1 on every SYNC. TPDO2 (type 2): 6401:2 on every 2nd.
  const Frame tpdo1(0x185, {0x12, 0x34, 0xFE, 0xFF});
  const Frame tpdo2(0x285, {0xFF, 0xFF});
  for (int sync = 1; sync <= 4; ++sync) {
    h->send(0x080, {});
    EXPECT_EQ(h->take(), sync % 2 ? Frames{tpdo1} : (Frames{tpdo1, tpdo2})) << "SYNC " << sync;
  }
  h->run_ms(1000);
  EXPECT_TRUE(h->take().empty());  // synchronous PDOs only on SYNC
  // Type 0 (acyclic synchronous): on SYNC only when the mapped data changed.
  ASSERT_EQ(h->write(0x1801, 2, 0, 1), 0u);
  h->send(0x080, {});
  EXPECT_EQ(h->take(), Frames{tpdo1});
  od().set<std::int16_t>(0x6401, 2, 300);
  h->send(0x080, {});
  EXPECT_EQ(h->take(), (Frames{tpdo1, Frame(0x285, {0x2C, 0x01})}));
  h->send(0x080, {});
  EXPECT_EQ(h->take(), Frames{tpdo1});
}

TEST_F(EdsNodeTest, RpdosUpdateTheirMappedObjects) {
  h->nmt(0x01, 5);
  h->take();
  // RPDO1: 6200:1, 6200:2.
  h->send(0x205, {0xAA, 0x55});
  EXPECT_EQ(h->read_u(0x6200, 1), 0xAAu);
  EXPECT_EQ(h->read_u(0x6200, 2), 0x55u);
  // RPDO2: 6411:1, a dummy byte (0x0005), 6411:2.
  h->send(0x305, {0x10, 0x27, 0x99, 0xE8, 0x03});
  EXPECT_EQ(h->read_u(0x6411, 1), 10000u);
  EXPECT_EQ(h->read_u(0x6411, 2), 1000u);
  // A PDO value cannot be refused: beyond HighLimit (10000) it is clamped.
  h->send(0x305, {0x98, 0x3A, 0x00, 0x00, 0x00});
  EXPECT_EQ(h->read_u(0x6411, 1), 10000u);
  EXPECT_EQ(h->read_u(0x6411, 2), 0u);
  // Too short: nothing written, EMCY 0x8210 (PDO not processed due to length error).
  h->take();
  h->send(0x205, {0x01});
  EXPECT_EQ(h->take(), Frames{Frame(0x085, {0x10, 0x82, 0x11, 0, 0, 0, 0, 0})});
  EXPECT_EQ(h->read_u(0x6200, 1), 0xAAu);
  // Not in pre-operational.
  h->nmt(0x80, 5);
  h->send(0x205, {0x01, 0x02});
  EXPECT_EQ(h->read_u(0x6200, 1), 0xAAu);
}

// ---- non-volatile memory --------------------------------------------------------------------------

TEST_F(EdsNodeTest, SavedValuesSurvivePowerCycleAndRestart) {
  const std::string store = vtest::unique_temp_path("vplant-eds-node");
  boot(store);
  ASSERT_EQ(h->write(0x2000, 0, 42, 1), 0u);
  ASSERT_EQ(h->download(0x2002, 0, {'s', 'a', 'v', 'e', 'd', ' ', 'l', 'a', 'b', 'e', 'l'}), 0u);
  ASSERT_EQ(h->write(0x1017, 0, 250, 2), 0u);
  ASSERT_EQ(h->write(0x1800, 2, 5, 1), 0u);
  ASSERT_EQ(h->write(0x1010, 1, kSave, 4), 0u);
  ASSERT_EQ(h->write(0x2000, 0, 43, 1), 0u);  // changed after the save: not kept
  // Power cycle of the same device.
  device->power_off();
  h->power_on();
  EXPECT_EQ(h->take(), Frames{Frame(0x705, {0x00})});
  EXPECT_EQ(h->read_u(0x2000, 0), 42u);
  EXPECT_EQ(h->read_u(0x1017, 0), 250u);
  // A new process on the same file (the kill -9 case is ParameterStore.KillDuringSave...).
  boot(store);
  EXPECT_EQ(h->read_u(0x2000, 0), 42u);
  const auto label = h->upload(0x2002, 0);
  ASSERT_TRUE(label);
  EXPECT_EQ(std::string(label->begin(), label->end()), "saved label");
  EXPECT_EQ(h->read_u(0x1800, 2), 5u);
  EXPECT_EQ(h->read_u(0x1800, 1), 0x185u);  // node-relative default stays relative
  // Restore defaults: in effect after the next reset.
  ASSERT_EQ(h->write(0x1011, 1, kLoad, 4), 0u);
  EXPECT_EQ(h->read_u(0x2000, 0), 42u);
  h->nmt(0x81, 5);
  h->run_ticks(1);
  EXPECT_EQ(h->read_u(0x2000, 0), 8u);
  EXPECT_EQ(h->read_u(0x1017, 0), 0u);
  std::remove(store.c_str());
}

// ---- loading ------------------------------------------------------------------------------------------

TEST(EdsNodeLoad, BrokenFileNamesFileAndLine) {
  const std::string path = vtest::unique_temp_path("vplant-eds-node", ".eds");
  {
    std::FILE* f = std::fopen(path.c_str(), "w");
    ASSERT_TRUE(f);
    std::fputs("[FileInfo]\nFileName=broken.eds\n[MandatoryObjects]\nSupportedObjects=one\n", f);
    std::fclose(f);
  }
  std::string error;
  EXPECT_FALSE(devices::EdsNode::load(path, {}, error));
  EXPECT_EQ(error, path + ":4: SupportedObjects: 'one' is not a number");
  std::remove(path.c_str());
  EXPECT_FALSE(devices::EdsNode::load("/nonexistent.eds", {}, error));
  EXPECT_EQ(error, "/nonexistent.eds: cannot open: No such file or directory");
}

TEST(EdsNodeLoad, OptionsAnEdsNodeDoesNotHave) {
  std::string error;
  devices::DeviceOptions options;
  options.variant = "big";
  EXPECT_FALSE(devices::EdsNode::load(kFixture, options, error));
  EXPECT_EQ(error, "an EDS node has no variants");
  options.variant.clear();
  options.settings["knob"] = "1";
  EXPECT_FALSE(devices::EdsNode::load(kFixture, options, error));
  EXPECT_EQ(error, "unknown setting 'knob' (no settings)");
}

TEST(EdsNodeLoad, DefaultNodeIdAndLssFromTheFile) {
  std::string error;
  auto plain = devices::EdsNode::load(kFixture, {}, error);
  ASSERT_TRUE(plain) << error;
  EXPECT_EQ(plain->node().node_id(), 1);  // no node-ID given: 1
  EXPECT_EQ(plain->node().lss(), nullptr);  // LSS_Supported=0
  auto lss = devices::EdsNode::load(VPLANT_TEST_DATA_DIR "/eds/compact_pdo.eds", {}, error);
  ASSERT_TRUE(lss) << error;
  EXPECT_NE(lss->node().lss(), nullptr);  // LSS_Supported=1
  EXPECT_EQ(lss->faults().size(), 2u);
}
