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

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;
using Bytes = std::vector<std::uint8_t>;

const char* const kVplant = VPLANT_BINARY;
constexpr std::uint8_t kNode = 5;

struct Frame {
  std::uint32_t id = 0;
  Bytes data;
  bool rtr = false;
  Clock::time_point at{};
};

class CanSocket {
 public:
  explicit CanSocket(const char* iface) {
    fd_ = ::socket(PF_CAN, SOCK_RAW, CAN_RAW);
    if (fd_ < 0) return;
    ifreq ifr{};
    std::snprintf(ifr.ifr_name, sizeof(ifr.ifr_name), "%s", iface);
    sockaddr_can addr{};
    addr.can_family = AF_CAN;
    if (::ioctl(fd_, SIOCGIFINDEX, &ifr) < 0) {
      ::close(fd_);
      fd_ = -1;
      return;
    }
    addr.can_ifindex = ifr.ifr_ifindex;
    if (::bind(fd_, reinterpret_cast<sockaddr*>(&addr), sizeof(addr)) < 0) {
      ::close(fd_);
      fd_ = -1;
    }
  }
  ~CanSocket() {
    if (fd_ >= 0) ::close(fd_);
  }
  CanSocket(const CanSocket&) = delete;
  CanSocket& operator=(const CanSocket&) = delete;
  bool ok() const { return fd_ >= 0; }

  void send(std::uint32_t id, Bytes data) {
    can_frame f{};
    f.can_id = id;
    f.can_dlc = static_cast<std::uint8_t>(data.size());
    std::copy(data.begin(), data.end(), f.data);
    ASSERT_EQ(::write(fd_, &f, sizeof(f)), static_cast<ssize_t>(sizeof(f)));
  }
  void send_rtr(std::uint32_t id, std::uint8_t dlc) {
    can_frame f{};
    f.can_id = id | CAN_RTR_FLAG;
    f.can_dlc = dlc;
    ASSERT_EQ(::write(fd_, &f, sizeof(f)), static_cast<ssize_t>(sizeof(f)));
  }

  /// The next frame for which `match` holds, within `timeout` (others are dropped).
  std::optional<Frame> wait_for(const std::function<bool(const Frame&)>& match, milliseconds timeout = milliseconds(3000)) {
    const auto deadline = Clock::now() + timeout;
    for (;;) {
      const auto left = std::chrono::duration_cast<milliseconds>(deadline - Clock::now()).count();
      if (left <= 0) return std::nullopt;
      pollfd pfd{fd_, POLLIN, 0};
      if (::poll(&pfd, 1, static_cast<int>(left)) <= 0) continue;
      can_frame f{};
      if (::read(fd_, &f, sizeof(f)) != static_cast<ssize_t>(sizeof(f))) continue;
      Frame got{f.can_id & CAN_SFF_MASK, Bytes(f.data, f.data + f.can_dlc), (f.can_id & CAN_RTR_FLAG) != 0, Clock::now()};
      if (match(got)) return got;
    }
  }
  std::optional<Frame> wait_for_id(std::uint32_t id, milliseconds timeout = milliseconds(3000)) {
    return wait_for([id](const Frame& f) { return f.id == id && !f.rtr; }, timeout);
  }
  void drain() {
    while (wait_for([](const Frame&) { return true; }, milliseconds(0))) {
    }
  }

 private:
  int fd_ = -1;
};

/// One SDO request on 0x605, its reply from 0x585 (8 data bytes; empty when none came).
Bytes sdo(CanSocket& can, Bytes request) {
  request.resize(8, 0);
  can.send(0x600 + kNode, request);
  auto r = can.wait_for_id(0x580 + kNode);
  return r ? r->data : Bytes{};
}

// A vplant child process with its stderr in a file.
class Vplant {
 public:
  explicit Vplant(const std::vector<std::string>& args) {
    char path[] = "/tmp/vplant-vtvpcd-stderr-XXXXXX";
    const int fd = ::mkstemp(path);
    stderr_path_ = path;
    pid_ = ::fork();
    if (pid_ == 0) {
      ::dup2(fd, 2);
      std::vector<char*> argv;
      argv.push_back(const_cast<char*>(kVplant));
      for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
      argv.push_back(nullptr);
      ::execv(kVplant, argv.data());
      std::perror("execv");
      ::_exit(127);
    }
    ::close(fd);
  }
  ~Vplant() {
    if (pid_ > 0) {
      ::kill(pid_, SIGTERM);
      ::waitpid(pid_, nullptr, 0);
    }
    std::remove(stderr_path_.c_str());
  }
  std::string stderr_text() const {
    std::ifstream in(stderr_path_);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
  }

 private:
  pid_t pid_ = -1;
  std::string stderr_path_;
};

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
