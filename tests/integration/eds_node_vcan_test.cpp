// `vplant node --eds` end to end over real SocketCAN: the vplant binary runs as a child process on
// vcan0 with the CiA 401-style fixture as node 5, and this program is the master, with raw CAN
// sockets. Registered through vplant_add_vcan_test, so it runs under tools/vcan/vcan-run
// (natively where the kernel has vcan, in a qemu guest elsewhere). Real time: waits are bounded
// by generous timeouts (the guest runs under TCG emulation), never by sleeps that must be right.
#include <fcntl.h>
#include <gtest/gtest.h>

#include "tests/support/temp_path.h"
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

const std::string kFixture = VPLANT_TEST_DATA_DIR "/eds/io_module.eds";
constexpr std::uint8_t kNode = 5;

std::vector<std::string> node_args(const std::string& store) {
  return {"node", "--eds", kFixture, "--node-id", "5", "--can", "vcan0", "--store", store};
}

bool is_boot_up(const Frame& f) { return f.id == 0x700u + kNode && f.data == std::vector<std::uint8_t>{0x00}; }

}  // namespace

TEST(EdsNodeVcan, ServicesSaveKillRestart) {
  CanSocket can("vcan0");
  ASSERT_TRUE(can.ok()) << "no vcan0 (run through tools/vcan/vcan-run)";
  SdoClient sdo(can, kNode);
  const std::string store = vtest::unique_temp_path("vplant-eds-store");
  auto node = std::make_unique<Vplant>(node_args(store));
  ASSERT_TRUE(can.wait_for(is_boot_up, milliseconds(10000))) << "no boot-up 0x705 [00]\n" << node->stderr_text();

  // Identity and a segmented string.
  EXPECT_EQ(sdo.read_u(0x1000, 0), 0x000F0191u);
  EXPECT_EQ(sdo.read_u(0x1018, 1), 0x00000ABCu);
  EXPECT_EQ(sdo.read_u(0x1018, 4), 0x00C0FFEEu);
  bool segmented = false;
  const auto name = sdo.upload(0x1008, 0, nullptr, &segmented);
  ASSERT_TRUE(name);
  EXPECT_TRUE(segmented);
  EXPECT_EQ(std::string(name->begin(), name->end()), "vplant IO-16 test module");
  // An abort: no object 0x3000.
  std::uint32_t abort = 0;
  EXPECT_FALSE(sdo.upload(0x3000, 0, &abort));
  EXPECT_EQ(abort, 0x06020000u);
  EXPECT_EQ(sdo.write(0x2000, 0, 201, 1), 0x06090031u);

  // Heartbeat at the 0x1017 period (100 ms), state pre-operational.
  ASSERT_EQ(sdo.write(0x1017, 0, 100, 2), 0u);
  std::vector<Clock::time_point> beats;
  for (int i = 0; i < 6; ++i) {
    auto hb = can.wait_for_id(0x700 + kNode, milliseconds(1000));
    ASSERT_TRUE(hb);
    EXPECT_EQ(hb->data, std::vector<std::uint8_t>{0x7F});
    beats.push_back(hb->at);
  }
  const auto mean_ms = std::chrono::duration_cast<std::chrono::microseconds>(beats.back() - beats.front()).count() / 5000.0;
  EXPECT_NEAR(mean_ms, 100.0, 15.0);

  // NMT start: TPDO1 (type 1) on every SYNC, TPDO2 (type 2) on every second one.
  can.send(0x000, {0x01, kNode});
  ASSERT_TRUE(can.wait_for([](const Frame& f) { return f.id == 0x705 && f.data == std::vector<std::uint8_t>{0x05}; }));
  can.drain();
  can.send(0x080, {});
  auto tpdo1 = can.wait_for_id(0x185);
  ASSERT_TRUE(tpdo1);
  EXPECT_EQ(tpdo1->data, (std::vector<std::uint8_t>{0x00, 0x00, 0x00, 0x00}));
  can.send(0x080, {});
  auto tpdo2 = can.wait_for_id(0x285);
  ASSERT_TRUE(tpdo2);
  EXPECT_EQ(tpdo2->data, (std::vector<std::uint8_t>{0xFF, 0xFF}));

  // RPDO1 writes 6200:1 and 6200:2; SDO reads them back.
  can.send(0x205, {0xAA, 0x55});
  EXPECT_EQ(sdo.read_u(0x6200, 1), 0xAAu);
  EXPECT_EQ(sdo.read_u(0x6200, 2), 0x55u);

  // Save, kill -9, restart: the saved values are back.
  ASSERT_EQ(sdo.write(0x2000, 0, 42, 1), 0u);
  ASSERT_EQ(sdo.write(0x1010, 1, 0x65766173, 4), 0u);  // "save"
  ASSERT_EQ(sdo.write(0x2000, 0, 43, 1), 0u);          // not saved
  node->kill9();
  can.drain();
  node = std::make_unique<Vplant>(node_args(store));
  ASSERT_TRUE(can.wait_for(is_boot_up, milliseconds(10000))) << node->stderr_text();
  EXPECT_EQ(sdo.read_u(0x2000, 0), 42u);
  EXPECT_EQ(sdo.read_u(0x1017, 0), 100u);
  EXPECT_TRUE(can.wait_for([](const Frame& f) { return f.id == 0x705 && f.data == std::vector<std::uint8_t>{0x7F}; },
                           milliseconds(1000)));
  node.reset();
  std::remove(store.c_str());
}

TEST(EdsNodeVcan, BrokenEdsExitsWithFileAndLine) {
  const std::string path = vtest::unique_temp_path("vplant-broken", ".eds");
  {
    std::ofstream out(path);
    out << "[FileInfo]\nFileName=broken.eds\n[MandatoryObjects]\nSupportedObjects=one\n";
  }
  Vplant node({"node", "--eds", path, "--node-id", "5", "--can", "vcan0"});
  EXPECT_EQ(node.wait_exit(), 2);
  EXPECT_NE(node.stderr_text().find(path + ":4: SupportedObjects: 'one' is not a number"), std::string::npos)
      << node.stderr_text();
  std::remove(path.c_str());
}

TEST(EdsNodeVcan, MissingInterfaceExitsNamingIt) {
  Vplant node({"node", "--eds", kFixture, "--node-id", "5", "--can", "nosuch0"});
  EXPECT_EQ(node.wait_exit(), 2);
  EXPECT_NE(node.stderr_text().find("nosuch0"), std::string::npos) << node.stderr_text();
}
