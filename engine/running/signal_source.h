// Resolved signals: a SignalExpr bound to the value it reads (a port's double, a field of the last
// frame with an identifier, a node's NMT state), or a sum of such terms. Reading a signal never
// allocates.
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "devices/canopen/node.h"
#include "sim/bus.h"
#include "engine/loading/signal_expression.h"

namespace scenario {

/// The last frame of each identifier that a signal decodes, per bus (fed by a tap on each bus).
class FrameFieldStore {
 public:
  struct Slot {
    int bus = 0;
    std::uint32_t id = 0;
    bool extended = false;
    bool seen = false;
    std::uint8_t dlc = 0;
    std::uint8_t data[8] = {};
  };
  /// The slot for (bus, id); created on first use (at build time, never while running).
  int slot(int bus, std::uint32_t id, bool extended);
  const Slot& get(int index) const { return slots_[static_cast<std::size_t>(index)]; }
  void on_frame(int bus, const sim::CanFrame& f);

 private:
  std::vector<Slot> slots_;
};

class Signal {
 public:
  Signal() = default;  ///< no source: reads NaN (a member assigned later)
  static Signal port(const double* value, double scale, double offset, std::string name);
  static Signal frame(const FrameFieldStore* store, int slot, FrameField field, double scale, double offset, std::string name);
  static Signal nmt_state(const canopen::Node* node, double scale, double offset, std::string name);
  /// `bus.NAME.load`: sim::Bus::load(), the occupied fraction of the last 100 ms.
  static Signal bus_load(const sim::Bus* bus, double scale, double offset, std::string name);
  /// `bus.NAME.NODE.tec|rec|error_state`: the fault confinement counters of an endpoint
  /// (error_state: 0 active, 1 passive, 2 bus-off).
  enum class Counter { Tec, Rec, State };
  static Signal bus_counter(const sim::Bus* bus, int endpoint, Counter counter, double scale, double offset, std::string name);

  double value() const {
    double v;
    switch (kind_) {
      case Kind::Port: v = *value_; break;
      case Kind::Frame: {
        const auto& s = store_->get(slot_);
        v = s.seen ? decode_field(field_, s.data, s.dlc) : std::numeric_limits<double>::quiet_NaN();
        break;
      }
      case Kind::Nmt: v = static_cast<double>(node_->powered() ? static_cast<int>(node_->nmt_state()) : 0); break;
      case Kind::BusLoad: v = bus_->load(); break;
      case Kind::BusCounter: {
        const auto& c = bus_->counters(endpoint_);
        v = counter_ == Counter::Tec ? c.tec : counter_ == Counter::Rec ? c.rec : static_cast<double>(static_cast<int>(c.state));
        break;
      }
      default: v = std::numeric_limits<double>::quiet_NaN();
    }
    v = v * scale_ + offset_;
    for (const auto& term : more_) v += term.value();
    return v;
  }
  /// Adds a further term of a sum (SignalExpr::more), resolved at build time.
  void add_term(Signal term) { more_.push_back(std::move(term)); }
  const std::string& name() const { return name_; }

 private:
  enum class Kind { None, Port, Frame, Nmt, BusLoad, BusCounter };
  /// What every kind shares; the factories add what their kind reads.
  Signal(Kind kind, double scale, double offset, std::string name);

  Kind kind_ = Kind::None;
  const sim::Bus* bus_ = nullptr;
  int endpoint_ = 0;
  Counter counter_ = Counter::Tec;
  const double* value_ = nullptr;
  const FrameFieldStore* store_ = nullptr;
  int slot_ = 0;
  FrameField field_;
  const canopen::Node* node_ = nullptr;
  double scale_ = 1, offset_ = 0;
  std::vector<Signal> more_;
  std::string name_;
};

}  // namespace scenario
