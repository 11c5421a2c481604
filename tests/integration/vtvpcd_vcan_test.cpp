// `vplant node --device vtvpcd` end to end over real SocketCAN: the vplant binary runs as a child
// process on vcan0 as node 5 (the node of the manual's examples) and this program is the master,
// with a raw CAN socket. Registered through vplant_add_vcan_test (runs under tools/vcan/vcan-run,
// in a qemu guest where the kernel has no vcan). Real time: waits are bounded by generous
// timeouts (the guest runs under TCG emulation), never by sleeps that must be right.
//
// The selection: boot-up and NMT with guarding, a parameter write with the manual's conversion
// example, the manual's PDO start sequence with the example mapping, a life-guarding EMCY, and
// the RAM-only resets.
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
#include <thread>
#include <vector>

namespace {

using namespace vtest::vcan;

// `vplant ...` as a child process, stderr kept for failure messages.
class Vplant : public ChildProcess {
 public:
  explicit Vplant(const std::vector<std::string>& args) : ChildProcess(VPLANT_BINARY, args) {}
};

constexpr std::uint8_t kNode = 5;

/// One SDO request on 0x605, its reply from 0x585 (8 data bytes; empty when none came).
Bytes sdo(CanSocket& can, Bytes request) { return SdoClient(can, kNode).exchange(std::move(request)); }

bool is_boot_up(const Frame& f) { return f.id == 0x700u + kNode && !f.rtr && f.data == Bytes{0x00}; }

}  // namespace

TEST(VtvpcdVcan, ManualSequencesEndToEnd) {
  CanSocket can("vcan0");
  ASSERT_TRUE(can.ok()) << "no vcan0 (run through tools/vcan/vcan-run)";
  Vplant node({"node", "--device", "vtvpcd", "--node-id", "5", "--can", "vcan0"});

  // Boot-up (300 ms after start), guarding in Pre-operational.
  ASSERT_TRUE(can.wait_for(is_boot_up, milliseconds(15000))) << "no boot-up 0x705 [00]\n" << node.stderr_text();
  can.send_rtr(0x705, 1);
  auto guard = can.wait_for_id(0x705);
  ASSERT_TRUE(guard);
  EXPECT_EQ(guard->data, Bytes{0x7F});

  // Parameter write with the manual's conversion: Power CMD (BUS) 4.0 % -> 1311 = 0x051F.
  EXPECT_EQ(sdo(can, {0x22, 0x76, 0x2C, 0x00, 0x1F, 0x05, 0x00, 0x00}), (Bytes{0x60, 0x76, 0x2C, 0x00, 0, 0, 0, 0}));
  EXPECT_EQ(sdo(can, {0x40, 0x76, 0x2C, 0x00}), (Bytes{0x43, 0x76, 0x2C, 0x00, 0x1F, 0x05, 0x00, 0x00}));
  std::this_thread::sleep_for(milliseconds(20));  // at least one control cycle
  EXPECT_EQ(sdo(can, {0x40, 0x18, 0x2F, 0x00}), (Bytes{0x43, 0x18, 0x2F, 0x00, 0x1F, 0x05, 0x00, 0x00}));
  // An abort from the manual's table.
  EXPECT_EQ(sdo(can, {0x23, 0x07, 0x2F, 0x00, 0, 0, 0, 0}), (Bytes{0x80, 0x07, 0x2F, 0x00, 0x00, 0x00, 0x01, 0x06}));

  // The manual's PDO start: event timer 100 ms (0x2B write, 0x42 read), NMT start node 5.
  EXPECT_EQ(sdo(can, {0x2B, 0x00, 0x18, 0x05, 0x64, 0x00, 0x00, 0x00}), (Bytes{0x60, 0x00, 0x18, 0x05, 0, 0, 0, 0}));
  EXPECT_EQ(sdo(can, {0x42, 0x00, 0x18, 0x05, 0x00, 0x00, 0x00, 0x00}), (Bytes{0x4B, 0x00, 0x18, 0x05, 0x64, 0x00, 0, 0}));
  EXPECT_FALSE(can.wait_for_id(0x185, milliseconds(300)));  // nothing before the start
  can.send(0x000, {0x01, kNode});
  std::vector<Clock::time_point> at;
  for (int i = 0; i < 6; ++i) {
    auto t = can.wait_for_id(0x185, milliseconds(2000));
    ASSERT_TRUE(t) << node.stderr_text();
    ASSERT_EQ(t->data.size(), 8u);  // act. pressure B + Discrete Outputs as 4 bytes
    EXPECT_EQ(t->data[6], 0x00);
    EXPECT_EQ(t->data[7], 0x00);
    at.push_back(t->at);
  }
  const double mean_ms = std::chrono::duration_cast<std::chrono::microseconds>(at.back() - at.front()).count() / 5000.0;
  EXPECT_NEAR(mean_ms, 100.0, 20.0);
  can.send_rtr(0x705, 1);
  guard = can.wait_for_id(0x705);
  ASSERT_TRUE(guard);
  EXPECT_EQ(guard->data, Bytes{0x85});  // toggled, Operational

  // RPDO1 of the example mapping: Trigger := set 3, Pressure CMD (BUS) := 39320.
  can.send(0x205, {0x08, 0x00, 0x00, 0x00, 0x98, 0x99, 0x00, 0x00});
  EXPECT_EQ(sdo(can, {0x40, 0x67, 0x2C, 0x00}), (Bytes{0x43, 0x67, 0x2C, 0x00, 0x08, 0x00, 0x00, 0x00}));
  EXPECT_EQ(sdo(can, {0x40, 0x74, 0x2C, 0x00}), (Bytes{0x43, 0x74, 0x2C, 0x00, 0x98, 0x99, 0x00, 0x00}));

  // Life guarding 100 ms x 3: one RTR, then silence -> EMCY 0x8100 and Bus Status fault 16.
  EXPECT_EQ(sdo(can, {0x2B, 0x0C, 0x10, 0x00, 0x64, 0x00, 0, 0}), (Bytes{0x60, 0x0C, 0x10, 0x00, 0, 0, 0, 0}));
  EXPECT_EQ(sdo(can, {0x2F, 0x0D, 0x10, 0x00, 0x03, 0x00, 0, 0}), (Bytes{0x60, 0x0D, 0x10, 0x00, 0, 0, 0, 0}));
  can.send_rtr(0x705, 1);
  ASSERT_TRUE(can.wait_for_id(0x705));
  auto emcy = can.wait_for_id(0x085, milliseconds(5000));
  ASSERT_TRUE(emcy) << node.stderr_text();
  EXPECT_EQ(emcy->data, (Bytes{0x00, 0x81, 0x11, 0x00, 0x00, 0x00, 0x00, 0x00}));
  EXPECT_EQ(sdo(can, {0x40, 0x68, 0x2C, 0x00}), (Bytes{0x4B, 0x68, 0x2C, 0x00, 0x10, 0x11, 0, 0}));
  EXPECT_EQ(sdo(can, {0x40, 0x01, 0x10, 0x00}), (Bytes{0x4F, 0x01, 0x10, 0x00, 0x11, 0, 0, 0}));

  // Reset communication: boot-up, event timer back to 0, manufacturer values kept.
  can.send(0x000, {0x82, kNode});
  ASSERT_TRUE(can.wait_for(is_boot_up, milliseconds(3000)));
  EXPECT_EQ(sdo(can, {0x40, 0x00, 0x18, 0x05}), (Bytes{0x4B, 0x00, 0x18, 0x05, 0, 0, 0, 0}));
  EXPECT_EQ(sdo(can, {0x40, 0x76, 0x2C, 0x00}), (Bytes{0x43, 0x76, 0x2C, 0x00, 0x1F, 0x05, 0x00, 0x00}));
  // Reset of the amplifier card: everything written over the bus is gone.
  can.send(0x000, {0x81, 0x00});
  ASSERT_TRUE(can.wait_for(is_boot_up, milliseconds(3000)));
  EXPECT_EQ(sdo(can, {0x40, 0x76, 0x2C, 0x00}), (Bytes{0x43, 0x76, 0x2C, 0x00, 0xFF, 0x7F, 0x00, 0x00}));
  EXPECT_EQ(sdo(can, {0x40, 0x68, 0x2C, 0x00}), (Bytes{0x4B, 0x68, 0x2C, 0x00, 0x00, 0x00, 0, 0}));
}
