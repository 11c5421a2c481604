// Helpers for end-to-end tests on real SocketCAN (run under tools/vcan/vcan-run): a raw CAN socket
// with bounded waits, an SDO client on it, and a vplant child process with its stderr captured.
// Waits are bounded by generous timeouts (the guest may run under TCG emulation), never sleeps
// that have to be right.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace vtest::vcan {

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;
using Bytes = std::vector<std::uint8_t>;

struct Frame {
  std::uint32_t id = 0;
  Bytes data;
  bool rtr = false;
  Clock::time_point at{};
};

class CanSocket {
 public:
  explicit CanSocket(const char* iface);
  ~CanSocket();
  CanSocket(const CanSocket&) = delete;
  CanSocket& operator=(const CanSocket&) = delete;
  bool ok() const { return fd_ >= 0; }

  /// Sends a data frame (records a test failure if the write fails).
  void send(std::uint32_t id, Bytes data);
  void send_rtr(std::uint32_t id, std::uint8_t dlc);
  /// The next frame for which `match` holds, within `timeout` (others are dropped).
  std::optional<Frame> wait_for(const std::function<bool(const Frame&)>& match, milliseconds timeout = milliseconds(5000));
  /// The next data frame with this identifier.
  std::optional<Frame> wait_for_id(std::uint32_t id, milliseconds timeout = milliseconds(5000));
  /// Sends `data` (padded to 8 bytes) on `id` and returns the first data frame on `reply_id`.
  std::optional<Frame> ask(std::uint32_t id, Bytes data, std::uint32_t reply_id, milliseconds timeout = milliseconds(5000));
  /// Drops everything queued.
  void drain();

 private:
  int fd_ = -1;
};

/// SDO client on 0x600+N / 0x580+N.
class SdoClient {
 public:
  SdoClient(CanSocket& can, std::uint8_t node) : can_(can), node_(node) {}

  /// One request (padded to 8 bytes) and its reply.
  std::optional<Frame> request(Bytes bytes);
  /// The reply's 8 bytes, empty when none came.
  Bytes exchange(Bytes bytes);
  /// Value bytes (expedited or segmented), or nullopt with `abort` set.
  std::optional<Bytes> upload(std::uint16_t index, std::uint8_t sub, std::uint32_t* abort = nullptr,
                              bool* segmented = nullptr);
  /// Little-endian value of an upload (a test failure if there is none).
  std::uint64_t read_u(std::uint16_t index, std::uint8_t sub);
  /// Expedited download of `size` bytes: 0 or the abort code (0xFFFFFFFF: no answer).
  std::uint32_t write(std::uint16_t index, std::uint8_t sub, std::uint32_t value, std::uint8_t size);
  static std::uint32_t abort_code(const Frame& f);

 private:
  CanSocket& can_;
  std::uint8_t node_;
};

/// A child process (normally the vplant binary) with stderr in a temporary file. The destructor
/// stops it (SIGTERM, then SIGKILL) if it is still running.
class ChildProcess {
 public:
  ChildProcess(const std::string& binary, const std::vector<std::string>& args);
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  /// Exit status within `timeout` (128 + signal if killed), or -1.
  int wait_exit(milliseconds timeout = milliseconds(10000));
  void signal(int sig);
  void kill9();
  std::string stderr_text() const;

 private:
  pid_t pid_ = -1;
  bool exited_ = false;
  std::string stderr_path_;
};

}  // namespace vtest::vcan
