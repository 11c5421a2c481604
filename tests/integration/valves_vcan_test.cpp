// The DSP 408 valves (MD2, DSV) end to end over real SocketCAN: `vplant node --device md2|dsv`
// runs as a child process on vcan0 and this program is the master, with raw CAN sockets. The
// selection of the issue: boot-up, identity reads, the commissioning sequence that reaches
// DEVICE_MODE_ACTIVE by PDO, a fault and its reset, EMCY on a cable break. Registered through
// vplant_add_vcan_test (docs/harness.md). Real time: waits are bounded by generous timeouts (the
// guest runs under TCG emulation), never by sleeps that must be right.
#include <fcntl.h>
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



bool frame_is(const Frame& f, std::uint32_t id, const Bytes& data) { return f.id == id && f.data == data; }

}  // namespace

TEST(ValvesVcan, Md2BootIdentityCommissioningFaultAndReset) {
  constexpr std::uint8_t kNode = 3;
  CanSocket can("vcan0");
  ASSERT_TRUE(can.ok()) << "no vcan0 (run through tools/vcan/vcan-run)";
  SdoClient sdo(can, kNode);
  Vplant node({"node", "--device", "md2", "--node-id", "3", "--can", "vcan0"});
  ASSERT_TRUE(can.wait_for([](const Frame& f) { return frame_is(f, 0x703, {0x00}); }, milliseconds(10000)))
      << "no boot-up 0x703 [00]\n" << node.stderr_text();

  // Identity.
  EXPECT_EQ(sdo.read_u(0x1000, 0), 0x10000198u);
  EXPECT_EQ(sdo.read_u(0x1018, 1), 0x0000014Du);
  const auto vendor = sdo.upload(0x6057, 0);
  ASSERT_TRUE(vendor);
  EXPECT_EQ(std::string(vendor->begin(), vendor->end()), "Wandfluh AG");
  EXPECT_EQ(sdo.read_u(0x6041, 0), 0x0008u);

  // Commissioning by PDO: start, control word 0x0007 and 50 % in RPDO1 → ACTIVE in TPDO1.
  can.send(0x000, {0x01, kNode});
  can.send(0x203, {0x07, 0x00, 0x00, 0x20});
  auto tpdo = can.wait_for_id(0x183);
  ASSERT_TRUE(tpdo);
  EXPECT_EQ(tpdo->data, (Bytes{0x0F, 0x00}));
  EXPECT_EQ(sdo.read_u(0x6300, 1), 0x2000u);

  // A fault: Reset Communication while ACTIVE → boot-up, then EMCY 0x8100; FAULT.
  can.drain();
  can.send(0x000, {0x82, kNode});
  ASSERT_TRUE(can.wait_for([](const Frame& f) { return frame_is(f, 0x703, {0x00}); }));
  auto emcy = can.wait_for_id(0x083);
  ASSERT_TRUE(emcy);
  EXPECT_EQ(emcy->data, (Bytes{0x00, 0x81, 0x11, 0x00, 0x00, 0x00, 0x00, 0x00}));
  EXPECT_EQ(sdo.read_u(0x6041, 0), 0x0001u);
  EXPECT_EQ(sdo.read_u(0x1001, 0), 0x11u);

  // Its reset: a rising edge of bit 3 → "no error" EMCY, DISABLED.
  can.send(0x000, {0x01, kNode});
  can.drain();
  can.send(0x203, {0x01, 0x00, 0x00, 0x00});
  tpdo = can.wait_for_id(0x183);
  ASSERT_TRUE(tpdo);
  EXPECT_EQ(tpdo->data, (Bytes{0x01, 0x00}));
  can.send(0x203, {0x09, 0x00, 0x00, 0x00});
  emcy = can.wait_for_id(0x083);
  ASSERT_TRUE(emcy);
  EXPECT_EQ(emcy->data, (Bytes{0, 0, 0, 0, 0, 0, 0, 0}));
  tpdo = can.wait_for_id(0x183);
  ASSERT_TRUE(tpdo);
  EXPECT_EQ(tpdo->data, (Bytes{0x09, 0x00}));
}

TEST(ValvesVcan, DsvControllerCommissioningAndCableBreakEmcy) {
  constexpr std::uint8_t kNode = 4;
  CanSocket can("vcan0");
  ASSERT_TRUE(can.ok()) << "no vcan0 (run through tools/vcan/vcan-run)";
  SdoClient sdo(can, kNode);
  // Pressure closed loop stored, bus operation; the sensor wire is broken from the start.
  Vplant node({"node", "--device", "dsv", "--variant", "controller", "--node-id", "4", "--can", "vcan0", "--setting",
               "device_local=0", "--setting", "control_mode=4", "--set", "actual_cable_break=1"});
  ASSERT_TRUE(can.wait_for([](const Frame& f) { return frame_is(f, 0x704, {0x00}); }, milliseconds(10000)))
      << "no boot-up 0x704 [00]\n" << node.stderr_text();

  EXPECT_EQ(sdo.read_u(0x1000, 0), 0x00000198u);
  EXPECT_EQ(sdo.read_u(0x1018, 1), 0x0000014Du);
  EXPECT_EQ(sdo.read_u(0x6043, 0), 4u);

  // Commissioning by PDO: RPDO1 (control word, pressure set point) is answered by TPDO2 (status
  // word, actual value) in mode 4.
  can.send(0x000, {0x01, kNode});
  can.send(0x204, {0x07, 0x00, 0x00, 0x20});
  auto tpdo = can.wait_for_id(0x284);
  ASSERT_TRUE(tpdo);
  EXPECT_EQ(tpdo->data, (Bytes{0x0F, 0x00, 0x00, 0x00}));

  // 4..20 mA input with cable-break detection: the broken wire reads 0 mA → EMCY 0x3422, FAULT.
  can.drain();
  ASSERT_EQ(sdo.write(0x2200, 0, 3, 1), 0u);
  ASSERT_EQ(sdo.write(0x2201, 0, 1, 1), 0u);
  auto emcy = can.wait_for_id(0x084);
  ASSERT_TRUE(emcy);
  EXPECT_EQ(emcy->data, (Bytes{0x22, 0x34, 0x05, 0x00, 0x00, 0x00, 0x00, 0x00}));
  EXPECT_EQ(sdo.read_u(0x6041, 0), 0x0001u);
  // A fault reset is refused while the wire is still broken.
  can.send(0x204, {0x00, 0x00, 0x00, 0x00});
  can.send(0x204, {0x08, 0x00, 0x00, 0x00});
  for (int i = 0; i < 2; ++i) {
    tpdo = can.wait_for_id(0x284);
    ASSERT_TRUE(tpdo);
    EXPECT_EQ(tpdo->data[0], 0x01);
  }
}
