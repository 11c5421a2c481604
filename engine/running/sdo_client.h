// The scripted master's SDO client (CiA 301 §7.2.4): expedited and segmented upload and download
// to one server at a time, toggle and multiplexer checks, abort handling and a timeout. It is fed
// the server's responses and sends requests through a callback; no allocation per segment.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "sim/can_frame.h"
#include "sim/time.h"

namespace scenario {

class SdoClient {
 public:
  enum class State { Idle, Busy, Done, Aborted, Failed };
  using Send = std::function<void(const sim::CanFrame&)>;

  explicit SdoClient(Send send) : send_(std::move(send)) {}

  void start_upload(std::uint8_t node_id, std::uint16_t index, std::uint8_t sub, sim::Time now, sim::Duration timeout);
  void start_download(std::uint8_t node_id, std::uint16_t index, std::uint8_t sub, const std::vector<std::uint8_t>& data,
                      sim::Time now, sim::Duration timeout);
  /// A frame from the bus; takes what belongs to the transfer in progress.
  void on_frame(const sim::CanFrame& f, sim::Time now);
  /// Checks the timeout (sends an abort 0x05040000 to the server when it expires).
  void poll(sim::Time now);

  State state() const { return state_; }
  bool busy() const { return state_ == State::Busy; }
  /// Upload: the data read. Download: the data written.
  const std::vector<std::uint8_t>& data() const { return data_; }
  /// Aborted: the server's abort code. Failed: the code this client sent.
  std::uint32_t abort_code() const { return abort_code_; }
  /// Failed: why (protocol violation, timeout).
  const std::string& error() const { return error_; }
  void reset() { state_ = State::Idle; }

 private:
  /// What an upload and a download set up alike: the object, the deadline, a clean state.
  void begin(std::uint8_t node_id, std::uint16_t index, std::uint8_t sub, bool upload, sim::Time now,
             sim::Duration timeout);
  void fail(std::uint32_t code, const std::string& why);
  void send(std::initializer_list<std::uint8_t> head, const std::uint8_t* tail = nullptr, std::size_t tail_len = 0);
  void next_download_segment();

  Send send_;
  State state_ = State::Idle;
  bool upload_ = true;
  bool segmented_ = false;
  bool toggle_ = false;
  std::uint8_t node_id_ = 0;
  std::uint16_t index_ = 0;
  std::uint8_t sub_ = 0;
  std::size_t offset_ = 0;
  std::size_t expected_size_ = 0;  ///< upload with size indication (0 = unknown)
  sim::Time deadline_{};
  sim::Duration timeout_{0};
  std::vector<std::uint8_t> data_;
  std::uint32_t abort_code_ = 0;
  std::string error_;
};

}  // namespace scenario
