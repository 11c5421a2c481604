// The CiA 406 encoders end to end over real SocketCAN: `vplant node --device hlt1100|wdga --can
// vcan0` as child processes, this program as the master with a raw CAN socket. Registered through
// vplant_add_vcan_test (tools/vcan/vcan-run: natively where the kernel has vcan, else in a qemu
// guest). Selection (issue 5): boot-up, SDO reads of identity, LSS node-ID change, PDO on SYNC,
// EMCY on magnet loss (HLT 1100) and on over-temperature (WDGA). Waits are bounded by generous
// timeouts (TCG emulation), never by sleeps that must be right.
#include <gtest/gtest.h>

#include "tests/support/vcan_master.h"
#include <linux/can.h>
#include <linux/can/raw.h>
#include <net/if.h>
#include <poll.h>
#include <signal.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace vtest::vcan;

// `vplant ...` as a child process, stderr kept for failure messages.
class Vplant : public ChildProcess {
 public:
  explicit Vplant(const std::vector<std::string>& args) : ChildProcess(VPLANT_BINARY, args) {}
};

Bytes eight(Bytes b) {
  b.resize(8, 0);
  return b;
}

TEST(EncodersVcan, Hlt1100) {
  CanSocket can("vcan0");
  ASSERT_TRUE(can.ok()) << "no vcan0 (run through tools/vcan/vcan-run)";
  // The magnet starts at 498.0 mm and moves out of the 500 mm range at 1 mm/s: lost after ~2 s.
  Vplant node({"node", "--device", "hlt1100", "--node-id", "5", "--can", "vcan0", "--set", "position=0.498",
               "--setting", "signal=ramp:0.001"});
  ASSERT_TRUE(can.wait_for([](const Frame& f) { return f.id == 0x705 && f.data == Bytes{0x00}; }, milliseconds(15000)))
      << "no boot-up 705#00\n" << node.stderr_text();
  // EMCY on magnet loss (it leaves the measuring range): FF00, error register 21h. Waited for
  // first, so no other wait can drop it.
  const auto emcy = can.wait_for_id(0x085, milliseconds(30000));
  ASSERT_TRUE(emcy) << node.stderr_text();
  EXPECT_EQ(emcy->data, eight({0x00, 0xFF, 0x21}));
  // Identity.
  auto r = can.ask(0x605, {0x40, 0x00, 0x10, 0x00}, 0x585);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->data, eight({0x43, 0x00, 0x10, 0x00, 0x96, 0x01, 0x0A, 0x00}));
  r = can.ask(0x605, {0x40, 0x18, 0x10, 0x01}, 0x585);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->data, eight({0x43, 0x18, 0x10, 0x01, 0xDA}));
  // PDO on SYNC (DLC 0) in Operational: TPDO2 keeps the last valid position, 4999 steps.
  can.send(0x000, {0x01, 0x05});
  ASSERT_TRUE(can.wait_for_id(0x185));  // the one-shot TPDO1 after Start
  can.send(0x080, {});
  const auto tpdo2 = can.wait_for_id(0x285);
  ASSERT_TRUE(tpdo2);
  EXPECT_EQ(tpdo2->data, (Bytes{0x87, 0x13, 0x00, 0x00}));
  // LSS node-ID change: configuration, node-ID 12, store, Reset Communication → boot-up 70C.
  can.send(0x7E5, eight({0x04, 0x01}));
  r = can.ask(0x7E5, {0x11, 0x0C}, 0x7E4);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->data, eight({0x11, 0x00}));
  r = can.ask(0x7E5, {0x17}, 0x7E4);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->data, eight({0x17, 0x00}));
  can.send(0x7E5, eight({0x04, 0x00}));
  can.send(0x000, {0x82, 0x05});
  ASSERT_TRUE(can.wait_for([](const Frame& f) { return f.id == 0x70C && f.data == Bytes{0x00}; }));
  r = can.ask(0x60C, {0x40, 0x00, 0x10, 0x00}, 0x58C);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->data[0], 0x43);
}

TEST(EncodersVcan, WdgaMultiturn) {
  CanSocket can("vcan0");
  ASSERT_TRUE(can.ok());
  Vplant node({"node", "--device", "wdga", "--can", "vcan0", "--set", "angle=6.283185307179586", "--set",
               "temperature=105"});
  // Automatic bit-rate detection: silent until another node sends; a SYNC (as in the manual).
  EXPECT_FALSE(can.wait_for_id(0x77F, milliseconds(1500))) << node.stderr_text();
  can.send(0x080, eight({}));
  ASSERT_TRUE(can.wait_for([](const Frame& f) { return f.id == 0x77F && f.data == Bytes{0x00}; }, milliseconds(15000)))
      << "no boot-up 77F#00\n" << node.stderr_text();
  // EMCY: the start-up temperature sample is above the 100 °C limit.
  const auto emcy = can.wait_for_id(0x0FF);
  ASSERT_TRUE(emcy);
  EXPECT_EQ(emcy->data, eight({0x00, 0x42, 0x08, 0x10}));
  // Identity.
  auto r = can.ask(0x67F, {0x40, 0x18, 0x10, 0x02}, 0x5FF);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->data, eight({0x43, 0x18, 0x10, 0x02, 0x41, 0x47, 0x44, 0x57}));
  r = can.ask(0x67F, {0x40, 0x00, 0x10, 0x00}, 0x5FF);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->data, eight({0x43, 0x00, 0x10, 0x00, 0x96, 0x01, 0x02, 0x00}));
  // PDO on SYNC: TPDO2 (6004h) and TPDO3 (6008h) show one turn = 16384.
  can.send(0x000, {0x01, 0x00});
  can.send(0x080, {});
  const auto tpdo2 = can.wait_for_id(0x2FF);
  ASSERT_TRUE(tpdo2);
  EXPECT_EQ(tpdo2->data, (Bytes{0x00, 0x40, 0x00, 0x00}));
  const auto tpdo3 = can.wait_for_id(0x3FF);
  ASSERT_TRUE(tpdo3);
  EXPECT_EQ(tpdo3->data, eight({0x00, 0x40}));
  // LSS (only in Stopped/Pre-operational): node-ID 5, stored; Reset Node applies it.
  can.send(0x000, {0x02, 0x7F});
  can.send(0x7E5, eight({0x04, 0x01}));
  r = can.ask(0x7E5, {0x11, 0x05}, 0x7E4);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->data, eight({0x11, 0x00}));
  r = can.ask(0x7E5, {0x17}, 0x7E4);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->data, eight({0x17, 0x00}));
  can.send(0x7E5, eight({0x04, 0x00}));
  can.send(0x000, {0x81, 0x7F});
  ASSERT_TRUE(can.wait_for([](const Frame& f) { return f.id == 0x705 && f.data == Bytes{0x00}; }));
  r = can.ask(0x605, {0x40, 0x01, 0x21, 0x00}, 0x585);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->data, eight({0x4F, 0x01, 0x21, 0x00, 0x05}));
}

}  // namespace
