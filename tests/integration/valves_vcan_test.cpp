// The DSP 408 valves (MD2, DSV) end to end over real SocketCAN: `vplant node --device md2|dsv`
// runs as a child process on vcan0 and this program is the master, with raw CAN sockets. The
// selection of the issue: boot-up, identity reads, the commissioning sequence that reaches
// DEVICE_MODE_ACTIVE by PDO, a fault and its reset, EMCY on a cable break. Registered through
// vplant_add_vcan_test (docs/harness.md). Real time: waits are bounded by generous timeouts (the
// guest runs under TCG emulation), never by sleeps that must be right.
#include <fcntl.h>
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

const char* const kVplant = VPLANT_BINARY;

struct Frame {
  std::uint32_t id = 0;
  std::vector<std::uint8_t> data;
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

  void send(std::uint32_t id, std::vector<std::uint8_t> data) {
    can_frame f{};
    f.can_id = id;
    f.can_dlc = static_cast<std::uint8_t>(data.size());
    std::copy(data.begin(), data.end(), f.data);
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
      Frame got{f.can_id & CAN_SFF_MASK, std::vector<std::uint8_t>(f.data, f.data + f.can_dlc), Clock::now()};
      if (match(got)) return got;
    }
  }
  std::optional<Frame> wait_for_id(std::uint32_t id, milliseconds timeout = milliseconds(3000)) {
    return wait_for([id](const Frame& f) { return f.id == id; }, timeout);
  }
  /// Drops everything queued.
  void drain() {
    while (wait_for([](const Frame&) { return true; }, milliseconds(0))) {
    }
  }

 private:
  int fd_ = -1;
};

// SDO client on 0x600+N / 0x580+N.
class SdoClient {
 public:
  SdoClient(CanSocket& can, std::uint8_t node) : can_(can), node_(node) {}

  std::optional<Frame> request(std::vector<std::uint8_t> bytes) {
    bytes.resize(8, 0);
    can_.send(0x600u + node_, bytes);
    return can_.wait_for_id(0x580u + node_);
  }
  /// Value bytes, or nullopt with `abort` set.
  std::optional<std::vector<std::uint8_t>> upload(std::uint16_t index, std::uint8_t sub, std::uint32_t* abort = nullptr,
                                                  bool* segmented = nullptr) {
    auto r = request({0x40, static_cast<std::uint8_t>(index), static_cast<std::uint8_t>(index >> 8), sub});
    if (!r) return std::nullopt;
    if (r->data[0] == 0x80) {
      if (abort) *abort = code(*r);
      return std::nullopt;
    }
    if ((r->data[0] & 0xE2) == 0x42) {
      const std::size_t n = (r->data[0] & 1) ? 4 - ((r->data[0] >> 2) & 3) : 4;
      if (segmented) *segmented = false;
      return std::vector<std::uint8_t>(r->data.begin() + 4, r->data.begin() + 4 + static_cast<std::ptrdiff_t>(n));
    }
    if (segmented) *segmented = true;
    std::vector<std::uint8_t> out;
    for (bool toggle = false;; toggle = !toggle) {
      auto s = request({static_cast<std::uint8_t>(0x60 | (toggle ? 0x10 : 0))});
      if (!s || s->data[0] == 0x80) return std::nullopt;
      const std::size_t n = 7 - ((s->data[0] >> 1) & 7);
      out.insert(out.end(), s->data.begin() + 1, s->data.begin() + 1 + static_cast<std::ptrdiff_t>(n));
      if (s->data[0] & 1) return out;
    }
  }
  std::uint64_t read_u(std::uint16_t index, std::uint8_t sub) {
    auto v = upload(index, sub);
    EXPECT_TRUE(v) << std::hex << index << ":" << int(sub);
    std::uint64_t u = 0;
    for (std::size_t i = 0; v && i < v->size() && i < 8; ++i) u |= static_cast<std::uint64_t>((*v)[i]) << (8 * i);
    return u;
  }
  /// Expedited download; 0 or the abort code (0xFFFFFFFF: no answer).
  std::uint32_t write(std::uint16_t index, std::uint8_t sub, std::uint32_t value, std::uint8_t size) {
    auto r = request({static_cast<std::uint8_t>(0x23 | ((4 - size) << 2)), static_cast<std::uint8_t>(index),
                      static_cast<std::uint8_t>(index >> 8), sub, static_cast<std::uint8_t>(value),
                      static_cast<std::uint8_t>(value >> 8), static_cast<std::uint8_t>(value >> 16),
                      static_cast<std::uint8_t>(value >> 24)});
    if (!r) return 0xFFFFFFFFu;
    return r->data[0] == 0x60 ? 0 : code(*r);
  }
  static std::uint32_t code(const Frame& f) {
    return static_cast<std::uint32_t>(f.data[4] | f.data[5] << 8 | f.data[6] << 16 | f.data[7] << 24);
  }

 private:
  CanSocket& can_;
  std::uint8_t node_;
};

// A vplant child process with its stderr in a file.
class Vplant {
 public:
  explicit Vplant(const std::vector<std::string>& args) {
    char path[] = "/tmp/vplant-valve-stderr-XXXXXX";
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
    if (pid_ > 0 && !exited_) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
    }
    std::remove(stderr_path_.c_str());
  }
  /// Exit status within `timeout`, or -1.
  int wait_exit(milliseconds timeout = milliseconds(10000)) {
    const auto deadline = Clock::now() + timeout;
    while (Clock::now() < deadline) {
      int status = 0;
      if (::waitpid(pid_, &status, WNOHANG) == pid_) {
        exited_ = true;
        return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
      }
      std::this_thread::sleep_for(milliseconds(10));
    }
    return -1;
  }
  void kill9() {
    ::kill(pid_, SIGKILL);
    ::waitpid(pid_, nullptr, 0);
    exited_ = true;
  }
  std::string stderr_text() const {
    std::ifstream in(stderr_path_);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
  }

 private:
  pid_t pid_ = -1;
  bool exited_ = false;
  std::string stderr_path_;
};

using Bytes = std::vector<std::uint8_t>;

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
