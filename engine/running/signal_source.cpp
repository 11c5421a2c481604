#include "engine/running/signal_source.h"

#include <algorithm>

namespace scenario {

int FrameFieldStore::slot(int bus, std::uint32_t id, bool extended) {
  for (std::size_t i = 0; i < slots_.size(); ++i) {
    const auto& s = slots_[i];
    if (s.bus == bus && s.id == id && s.extended == extended) return static_cast<int>(i);
  }
  Slot s;
  s.bus = bus;
  s.id = id;
  s.extended = extended;
  slots_.push_back(s);
  return static_cast<int>(slots_.size()) - 1;
}

void FrameFieldStore::on_frame(int bus, const sim::CanFrame& f) {
  if (f.rtr) return;
  for (auto& s : slots_) {
    if (s.bus != bus || s.id != f.id || s.extended != f.extended) continue;
    s.seen = true;
    s.dlc = f.dlc;
    std::copy(f.data.begin(), f.data.end(), s.data);
  }
}

Signal::Signal(Kind kind, double scale, double offset, std::string name)
    : kind_(kind), scale_(scale), offset_(offset), name_(std::move(name)) {}

Signal Signal::port(const double* value, double scale, double offset, std::string name) {
  Signal s(Kind::Port, scale, offset, std::move(name));
  s.value_ = value;
  return s;
}

Signal Signal::frame(const FrameFieldStore* store, int slot, FrameField field, double scale, double offset, std::string name) {
  Signal s(Kind::Frame, scale, offset, std::move(name));
  s.store_ = store;
  s.slot_ = slot;
  s.field_ = field;
  return s;
}

Signal Signal::nmt_state(const canopen::Node* node, double scale, double offset, std::string name) {
  Signal s(Kind::Nmt, scale, offset, std::move(name));
  s.node_ = node;
  return s;
}

Signal Signal::bus_load(const sim::Bus* bus, double scale, double offset, std::string name) {
  Signal s(Kind::BusLoad, scale, offset, std::move(name));
  s.bus_ = bus;
  return s;
}

Signal Signal::bus_counter(const sim::Bus* bus, int endpoint, Counter counter, double scale, double offset, std::string name) {
  Signal s(Kind::BusCounter, scale, offset, std::move(name));
  s.bus_ = bus;
  s.endpoint_ = endpoint;
  s.counter_ = counter;
  return s;
}

}  // namespace scenario
