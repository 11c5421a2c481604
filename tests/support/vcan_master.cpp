#include "tests/support/vcan_master.h"

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

#include <cstdio>
#include <fstream>
#include <sstream>
#include <thread>

namespace vtest::vcan {

CanSocket::CanSocket(const char* iface) {
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

CanSocket::~CanSocket() {
  if (fd_ >= 0) ::close(fd_);
}

void CanSocket::send(std::uint32_t id, Bytes data) {
  can_frame f{};
  f.can_id = id;
  f.can_dlc = static_cast<std::uint8_t>(data.size());
  std::copy(data.begin(), data.end(), f.data);
  EXPECT_EQ(::write(fd_, &f, sizeof(f)), static_cast<ssize_t>(sizeof(f)));
}

void CanSocket::send_rtr(std::uint32_t id, std::uint8_t dlc) {
  can_frame f{};
  f.can_id = id | CAN_RTR_FLAG;
  f.can_dlc = dlc;
  EXPECT_EQ(::write(fd_, &f, sizeof(f)), static_cast<ssize_t>(sizeof(f)));
}

std::optional<Frame> CanSocket::wait_for(const std::function<bool(const Frame&)>& match, milliseconds timeout) {
  const auto deadline = Clock::now() + timeout;
  for (;;) {
    const auto left = std::chrono::duration_cast<milliseconds>(deadline - Clock::now()).count();
    if (left < 0) return std::nullopt;
    pollfd pfd{fd_, POLLIN, 0};
    if (::poll(&pfd, 1, static_cast<int>(left)) <= 0) {
      if (left == 0) return std::nullopt;
      continue;
    }
    can_frame f{};
    if (::read(fd_, &f, sizeof(f)) != static_cast<ssize_t>(sizeof(f))) continue;
    Frame got{f.can_id & CAN_SFF_MASK, Bytes(f.data, f.data + f.can_dlc), (f.can_id & CAN_RTR_FLAG) != 0, Clock::now()};
    if (got.rtr) got.data.clear();
    if (match(got)) return got;
  }
}

std::optional<Frame> CanSocket::wait_for_id(std::uint32_t id, milliseconds timeout) {
  return wait_for([id](const Frame& f) { return f.id == id && !f.rtr; }, timeout);
}

std::optional<Frame> CanSocket::ask(std::uint32_t id, Bytes data, std::uint32_t reply_id, milliseconds timeout) {
  data.resize(8, 0);
  send(id, std::move(data));
  return wait_for_id(reply_id, timeout);
}

void CanSocket::drain() {
  while (wait_for([](const Frame&) { return true; }, milliseconds(0))) {
  }
}

std::optional<Frame> SdoClient::request(Bytes bytes) {
  bytes.resize(8, 0);
  can_.send(0x600u + node_, bytes);
  return can_.wait_for_id(0x580u + node_);
}

Bytes SdoClient::exchange(Bytes bytes) {
  auto r = request(std::move(bytes));
  return r ? r->data : Bytes{};
}

std::uint32_t SdoClient::abort_code(const Frame& f) {
  if (f.data.size() < 8) return 0;
  return static_cast<std::uint32_t>(f.data[4] | f.data[5] << 8 | f.data[6] << 16 | f.data[7] << 24);
}

std::optional<Bytes> SdoClient::upload(std::uint16_t index, std::uint8_t sub, std::uint32_t* abort, bool* segmented) {
  auto r = request({0x40, static_cast<std::uint8_t>(index), static_cast<std::uint8_t>(index >> 8), sub});
  if (!r || r->data.size() < 8) return std::nullopt;
  if (r->data[0] == 0x80) {
    if (abort) *abort = abort_code(*r);
    return std::nullopt;
  }
  if ((r->data[0] & 0xE2) == 0x42) {
    const std::size_t n = (r->data[0] & 1) ? 4 - ((r->data[0] >> 2) & 3) : 4;
    if (segmented) *segmented = false;
    return Bytes(r->data.begin() + 4, r->data.begin() + 4 + static_cast<std::ptrdiff_t>(n));
  }
  if (segmented) *segmented = true;
  Bytes out;
  for (bool toggle = false;; toggle = !toggle) {
    auto s = request({static_cast<std::uint8_t>(0x60 | (toggle ? 0x10 : 0))});
    if (!s || s->data.size() < 8) return std::nullopt;
    if (s->data[0] == 0x80) {
      if (abort) *abort = abort_code(*s);
      return std::nullopt;
    }
    const std::size_t n = 7 - ((s->data[0] >> 1) & 7);
    out.insert(out.end(), s->data.begin() + 1, s->data.begin() + 1 + static_cast<std::ptrdiff_t>(n));
    if (s->data[0] & 1) return out;
  }
}

std::uint64_t SdoClient::read_u(std::uint16_t index, std::uint8_t sub) {
  auto v = upload(index, sub);
  EXPECT_TRUE(v) << std::hex << index << ":" << int(sub);
  std::uint64_t u = 0;
  for (std::size_t i = 0; v && i < v->size() && i < 8; ++i) u |= static_cast<std::uint64_t>((*v)[i]) << (8 * i);
  return u;
}

std::uint32_t SdoClient::write(std::uint16_t index, std::uint8_t sub, std::uint32_t value, std::uint8_t size) {
  auto r = request({static_cast<std::uint8_t>(0x23 | ((4 - size) << 2)), static_cast<std::uint8_t>(index),
                    static_cast<std::uint8_t>(index >> 8), sub, static_cast<std::uint8_t>(value),
                    static_cast<std::uint8_t>(value >> 8), static_cast<std::uint8_t>(value >> 16),
                    static_cast<std::uint8_t>(value >> 24)});
  if (!r) return 0xFFFFFFFFu;
  return r->data[0] == 0x60 ? 0 : abort_code(*r);
}

ChildProcess::ChildProcess(const std::string& binary, const std::vector<std::string>& args) {
  char path[] = "/tmp/vplant-child-stderr-XXXXXX";
  const int fd = ::mkstemp(path);
  stderr_path_ = path;
  pid_ = ::fork();
  if (pid_ == 0) {
    ::dup2(fd, 2);
    std::vector<char*> argv;
    argv.push_back(const_cast<char*>(binary.c_str()));
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(binary.c_str(), argv.data());
    std::perror("execv");
    ::_exit(127);
  }
  ::close(fd);
}

ChildProcess::~ChildProcess() {
  if (pid_ > 0 && !exited_) {
    ::kill(pid_, SIGTERM);
    if (wait_exit(milliseconds(3000)) < 0) kill9();
  }
  std::remove(stderr_path_.c_str());
}

int ChildProcess::wait_exit(milliseconds timeout) {
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

void ChildProcess::signal(int sig) { ::kill(pid_, sig); }

void ChildProcess::kill9() {
  ::kill(pid_, SIGKILL);
  ::waitpid(pid_, nullptr, 0);
  exited_ = true;
}

std::string ChildProcess::stderr_text() const {
  std::ifstream in(stderr_path_);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace vtest::vcan
