// `vplant node --eds` end to end over real SocketCAN: the vplant binary runs as a child process on
// vcan0 with the CiA 401-style fixture as node 5, and this program is the master, with raw CAN
// sockets. Registered through vplant_add_vcan_test, so it runs under tools/vcan/vcan-run
// (natively where the kernel has vcan, in a qemu guest elsewhere). Real time: waits are bounded
// by generous timeouts (the guest runs under TCG emulation), never by sleeps that must be right.
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
const std::string kFixture = VPLANT_TEST_DATA_DIR "/eds/io_module.eds";
constexpr std::uint8_t kNode = 5;

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
  explicit SdoClient(CanSocket& can) : can_(can) {}

  std::optional<Frame> request(std::vector<std::uint8_t> bytes) {
    bytes.resize(8, 0);
    can_.send(0x600 + kNode, bytes);
    return can_.wait_for_id(0x580 + kNode);
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
};

// A vplant child process with its stderr in a file.
class Vplant {
 public:
  explicit Vplant(const std::vector<std::string>& args) {
    char path[] = "/tmp/vplant-eds-stderr-XXXXXX";
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

std::string temp_path(const char* stem) {
  char path[64];
  std::snprintf(path, sizeof(path), "/tmp/%s-XXXXXX", stem);
  const int fd = ::mkstemp(path);
  ::close(fd);
  std::remove(path);
  return path;
}

std::vector<std::string> node_args(const std::string& store) {
  return {"node", "--eds", kFixture, "--node-id", "5", "--can", "vcan0", "--store", store};
}

bool is_boot_up(const Frame& f) { return f.id == 0x700u + kNode && f.data == std::vector<std::uint8_t>{0x00}; }

}  // namespace

TEST(EdsNodeVcan, ServicesSaveKillRestart) {
  CanSocket can("vcan0");
  ASSERT_TRUE(can.ok()) << "no vcan0 (run through tools/vcan/vcan-run)";
  SdoClient sdo(can);
  const std::string store = temp_path("vplant-eds-store");
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
  const std::string path = temp_path("vplant-broken") + ".eds";
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
