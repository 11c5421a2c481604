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

Signal Signal::port(const double* value, double scale, double offset, std::string name) {
  Signal s;
  s.kind_ = Kind::Port;
  s.value_ = value;
  s.scale_ = scale;
  s.offset_ = offset;
  s.name_ = std::move(name);
  return s;
}

Signal Signal::frame(const FrameFieldStore* store, int slot, FrameField field, double scale, double offset, std::string name) {
  Signal s;
  s.kind_ = Kind::Frame;
  s.store_ = store;
  s.slot_ = slot;
  s.field_ = field;
  s.scale_ = scale;
  s.offset_ = offset;
  s.name_ = std::move(name);
  return s;
}

Signal Signal::nmt_state(const canopen::Node* node, double scale, double offset, std::string name) {
  Signal s;
  s.kind_ = Kind::Nmt;
  s.node_ = node;
  s.scale_ = scale;
  s.offset_ = offset;
  s.name_ = std::move(name);
  return s;
}

Signal Signal::bus_load(const sim::Bus* bus, double scale, double offset, std::string name) {
  Signal s;
  s.kind_ = Kind::BusLoad;
  s.bus_ = bus;
  s.scale_ = scale;
  s.offset_ = offset;
  s.name_ = std::move(name);
  return s;
}

Signal Signal::bus_counter(const sim::Bus* bus, int endpoint, Counter counter, double scale, double offset, std::string name) {
  Signal s;
  s.kind_ = Kind::BusCounter;
  s.bus_ = bus;
  s.endpoint_ = endpoint;
  s.counter_ = counter;
  s.scale_ = scale;
  s.offset_ = offset;
  s.name_ = std::move(name);
  return s;
}

}  // namespace scenario
