// Frame-level test harness: one emulated node and a scripted master on a virtual bus, driven in
// virtual time. Tests read as "bytes in, bytes out":
//   h.send(0x605, {0x40, 0x00, 0x10, 0x00});
//   EXPECT_EQ(h.take(), Frames{{0x585, {0x43, 0x00, 0x10, 0x00, 0x98, 0x01, 0x00, 0x00}}});
#pragma once

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "devices/canopen/node.h"
#include "sim/bus.h"
#include "sim/scheduler.h"

namespace vtest {

/// A frame as tests write it: id, data bytes (or RTR with a DLC).
struct Frame {
  std::uint32_t id = 0;
  std::vector<std::uint8_t> data;
  bool rtr = false;
  std::uint8_t rtr_dlc = 0;

  Frame() = default;
  Frame(std::uint32_t i, std::initializer_list<std::uint8_t> d) : id(i), data(d) {}
  Frame(std::uint32_t i, std::vector<std::uint8_t> d) : id(i), data(std::move(d)) {}
  static Frame remote(std::uint32_t id, std::uint8_t dlc) {
    Frame f;
    f.id = id;
    f.rtr = true;
    f.rtr_dlc = dlc;
    return f;
  }
  static Frame from(const sim::CanFrame& f);
  sim::CanFrame to_can() const;
  bool operator==(const Frame& o) const = default;
};
using Frames = std::vector<Frame>;
std::ostream& operator<<(std::ostream& os, const Frame& f);

/// Records everything on the bus that the master did not send itself.
class Master : public sim::FrameReceiver {
 public:
  void on_frame(const sim::CanFrame& f, sim::Time now) override {
    frames.push_back(Frame::from(f));
    times.push_back(now);
  }
  Frames frames;
  std::vector<sim::Time> times;
};

class CanopenHarness {
 public:
  /// Builds the node (not yet powered). Call power_on() to boot it.
  CanopenHarness(canopen::ObjectDictionary od, canopen::NodePolicy policy, std::uint8_t node_id,
                 canopen::Application* app = nullptr);
  /// Takes an already-built node (a product) and attaches it.
  explicit CanopenHarness(canopen::Node& external_node);

  canopen::Node& node() { return *node_; }
  sim::Scheduler& scheduler() { return scheduler_; }
  sim::Bus& bus() { return bus_; }
  sim::Time now() const { return scheduler_.now(); }

  /// Powers the node on and runs one tick (boot-up goes out with a zero boot delay).
  void power_on();
  /// Sends a frame from the master and delivers it (replies arrive immediately).
  void send(const Frame& f);
  void send(std::uint32_t id, std::initializer_list<std::uint8_t> data) { send(Frame(id, data)); }
  /// Advances virtual time.
  void run_ms(std::int64_t ms) { scheduler_.run_for(sim::milliseconds(ms)); }
  void run_ticks(std::uint64_t n) { scheduler_.run_ticks(n); }
  /// Frames the master received since the last take(), then clears them.
  Frames take();
  std::vector<sim::Time> take_times();
  /// Runs 1 ms at a time from `since` until the master receives something or `limit` has passed
  /// since `since`: the frames, and how long after `since` the tick that sent them started.
  struct FirstFrames {
    Frames frames;
    sim::Duration at{};
  };
  FirstFrames run_until_frames(sim::Time since, sim::Duration limit);

  // --- SDO client helpers (node-ID based COB-IDs) ----------------------------------------------
  std::uint8_t id() const { return node_->node_id(); }
  /// Sends an 8-byte request and returns the single reply (empty if none or several).
  std::optional<Frame> sdo(std::initializer_list<std::uint8_t> request);
  /// Expedited upload; nullopt with `abort` set if the server aborted.
  std::optional<std::vector<std::uint8_t>> read(std::uint16_t index, std::uint8_t sub, std::uint32_t* abort = nullptr);
  std::optional<std::uint64_t> read_u(std::uint16_t index, std::uint8_t sub, std::uint32_t* abort = nullptr);
  /// Expedited download of `size` bytes (1..4); returns 0 on success or the abort code.
  std::uint32_t write(std::uint16_t index, std::uint8_t sub, std::uint32_t value, std::uint8_t size);
  /// Segmented (or expedited) upload of any size; returns the data or nullopt (abort set).
  std::optional<std::vector<std::uint8_t>> upload(std::uint16_t index, std::uint8_t sub, std::uint32_t* abort = nullptr);
  /// Segmented download; 0 or abort code.
  std::uint32_t download(std::uint16_t index, std::uint8_t sub, const std::vector<std::uint8_t>& data);
  void nmt(std::uint8_t command, std::uint8_t target = 0) { send(0x000, {command, target}); }

 private:
  void wire();

  sim::Bus bus_{"vcan-test"};
  Master master_;
  int master_ep_ = -1;
  std::optional<canopen::Node> owned_;
  canopen::Node* node_ = nullptr;
  sim::Scheduler scheduler_;
};

}  // namespace vtest
