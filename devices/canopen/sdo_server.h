// SDO server (CiA 301 §7.2.4): expedited and segmented upload/download with toggle checking,
// size indication, transfer timeout and abort codes. Knows frames and the object dictionary only.
#pragma once

#include <cstdint>
#include <optional>

#include "devices/canopen/node_policy.h"
#include "devices/canopen/object_dictionary.h"
#include "devices/canopen/service_links.h"
#include "sim/can_frame.h"
#include "sim/time.h"

namespace canopen {

class SdoServer {
 public:
  /// `status`: node-ID (default COB-IDs) and silence (a response waits until it ends).
  SdoServer(ObjectDictionary& od, const SdoPolicy& policy, const NodeStatus& status, FrameSender& sender);

  /// COB-IDs in use (from 0x1200 if present, else the predefined connection set).
  std::uint32_t rx_cob_id() const;
  std::uint32_t tx_cob_id() const;

  void on_request(const sim::CanFrame& frame, sim::Time now);
  void process(sim::Time now);
  /// Drops any transfer in progress without a frame (NMT reset, power-off).
  void reset();
  bool busy() const { return state_ != State::Idle; }
  /// process() has nothing to do: no transfer to time out, no response held back.
  bool idle() const { return state_ == State::Idle && !deferred_; }

 private:
  enum class State : std::uint8_t { Idle, Download, Upload };

  void initiate_download(const std::uint8_t* req);
  void download_segment(const std::uint8_t* req);
  void initiate_upload(const std::uint8_t* req);
  void upload_segment(const std::uint8_t* req);
  /// Adapts `data` to the entry's size per the policy; abort code if it cannot.
  SdoAbort fit_size(const OdEntry& e, Bytes& data, bool size_indicated) const;
  void respond(const std::array<std::uint8_t, 8>& bytes);
  void abort(std::uint16_t index, std::uint8_t sub, SdoAbort code);

  ObjectDictionary& od_;
  const SdoPolicy& policy_;
  const NodeStatus& status_;
  FrameSender& sender_;
  State state_ = State::Idle;
  std::uint16_t index_ = 0;
  std::uint8_t sub_ = 0;
  OdEntry* entry_ = nullptr;
  bool toggle_ = false;
  bool size_indicated_ = false;
  std::size_t expected_size_ = 0;
  std::size_t offset_ = 0;
  Bytes buffer_;
  sim::Time last_activity_{};
  std::optional<sim::CanFrame> deferred_;  // response held back while the node is silent
};

}  // namespace canopen
