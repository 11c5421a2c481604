#include "engine/running/fault_injector.h"

#include <memory>

namespace scenario {

FaultInjector::FaultInjector(World& world, Verdicts& verdicts, Log log)
    : world_(world), verdicts_(verdicts), log_(std::move(log)) {
  for (auto& bus : world_.buses()) {
    filters_.push_back(std::make_unique<WireFaultFilter>(&world_.random()));
    bus->set_filter(filters_.back().get());
  }
  for (const auto& f : world_.scenario().faults) {
    check(f);
    Scheduled s{&f, {}, false};
    if (f.when) s.when = world_.resolve(f.when->signal);
    scheduled_.push_back(std::move(s));
  }
}

NodeInstance& FaultInjector::node(const std::string& name) {
  auto* n = world_.find_node(name);
  return *n;  // check() guarantees it exists
}

void FaultInjector::check(const FaultSpec& f) {
  const auto need_node = [&](const std::string& name) -> NodeInstance& {
    auto* n = world_.find_node(name);
    if (!n) throw LoadError(f.mark, "fault: no node '" + name + "'");
    return *n;
  };
  if (f.when) world_.resolve(f.when->signal);
  std::visit(
      [&](const auto& a) {
        using T = std::decay_t<decltype(a)>;
        if constexpr (std::is_same_v<T, WireFault>) {
          if (a.kind == WireFault::Kind::TxError) need_node(a.node);
          else if (world_.bus_index(a.bus) < 0) throw LoadError(f.mark, "fault: unknown bus '" + a.bus + "'");
        } else if constexpr (std::is_same_v<T, BusOff> || std::is_same_v<T, Power>) {
          need_node(a.node);
        } else if constexpr (std::is_same_v<T, DeviceFault>) {
          auto& n = need_node(a.node);
          bool known = false;
          std::string names;
          for (const auto& fi : n.device->faults()) {
            known |= fi.name == a.fault;
            names += (names.empty() ? "" : ", ") + fi.name;
          }
          if (!known)
            throw LoadError(f.mark, "fault: node '" + a.node + "' (" + n.spec->device + ") has no fault '" + a.fault +
                                        "' (faults: " + (names.empty() ? "none" : names) + ")");
        } else if constexpr (std::is_same_v<T, PlantParameter>) {
          if (!world_.plant()) throw LoadError(f.mark, "fault: the scenario has no plant");
          if (!world_.plant()->parameter(a.name))
            throw LoadError(f.mark, "fault: the plant has no parameter '" + a.name + "'");
        }
      },
      f.action);
}

void FaultInjector::apply(const FaultSpec& f, sim::Time now) {
  auto clear = apply_now(f, now, nullptr);
  if (f.duration && clear) undo_.push_back({now + *f.duration, std::move(clear)});
}

FaultInjector::Injected FaultInjector::inject(const FaultSpec& f, sim::Time now) {
  check(f);
  std::string refused;
  auto clear = apply_now(f, now, &refused);
  if (!refused.empty()) throw LoadError(f.mark, "fault: " + refused);
  if (!clear) return {};
  Injected out;
  if (const auto* power = std::get_if<Power>(&f.action); power && power->kind == Power::Kind::Off) {
    const auto* canopen_node = &node(power->node).device->node();
    out.over = [canopen_node, off = canopen_node->power_ons()] { return canopen_node->power_ons() != off; };
  }
  // Ended by whichever comes first, the caller or `for:`; the other then does nothing.
  auto once = std::make_shared<Clear>(std::move(clear));
  Clear end = [once](sim::Time t) {
    if (!*once) return;
    Clear c = std::move(*once);
    *once = nullptr;
    c(t);
  };
  if (f.duration) undo_.push_back({now + *f.duration, end});
  out.clear = std::move(end);
  return out;
}

/// Ends a power-off: powers the node on unless it got power since (a power-on, reset or cycle in
/// between), which would otherwise boot it a second time.
static FaultInjector::Clear power_on_unless_powered_since(devices::Device* device) {
  return [device, off = device->node().power_ons()](sim::Time t) {
    if (device->node().power_ons() == off) device->power_on(t);
  };
}

FaultInjector::Clear FaultInjector::apply_now(const FaultSpec& f, sim::Time now, std::string* refused) {
  const auto note = [&] {
    ++applied_;
    if (log_) log_(now, "fault: " + f.summary + (f.duration ? " for " + format_value(sim::seconds(*f.duration)) + " s" : ""));
  };
  if (!refused) note();
  Clear clear;
  std::visit(
      [&](const auto& a) {
        using T = std::decay_t<decltype(a)>;
        if constexpr (std::is_same_v<T, WireFault>) {
          int bus = world_.bus_index(a.bus);
          WireFault rule = a;
          if (a.kind == WireFault::Kind::TxError) {  // the node's own bus and endpoint
            bus = node(a.node).bus;
            rule.endpoint = node(a.node).device->node().endpoint();
          }
          auto* filter = filters_[static_cast<std::size_t>(bus)].get();
          const int handle = filter->add(rule);
          clear = [filter, handle](sim::Time) { filter->remove(handle); };
        } else if constexpr (std::is_same_v<T, BusOff>) {
          auto& n = node(a.node);
          auto* bus = world_.buses()[static_cast<std::size_t>(n.bus)].get();
          const int ep = n.device->node().endpoint();
          bus->set_online(ep, false);
          auto* canopen_node = &n.device->node();
          clear = [bus, ep, canopen_node](sim::Time) {
            bus->set_online(ep, true);
            // Back from bus-off: the node's communication-error reaction (0x1029).
            canopen_node->communication_error(canopen::CommError::BusOffRecovered);
          };
        } else if constexpr (std::is_same_v<T, DeviceFault>) {
          auto* device = node(a.node).device.get();
          if (auto err = device->inject_fault(a.fault, a.active); !err.empty()) {
            if (refused) {
              *refused = err;
              return;
            }
            verdicts_.fail("fault " + f.summary, f.mark, now, "fault applied", err);
            return;
          }
          const std::string name = a.fault;
          const bool active = a.active;
          clear = [device, name, active](sim::Time) { device->inject_fault(name, !active); };
        } else if constexpr (std::is_same_v<T, Power>) {
          auto* device = node(a.node).device.get();
          switch (a.kind) {
            case Power::Kind::Off:
              device->power_off();
              clear = power_on_unless_powered_since(device);
              break;
            case Power::Kind::On: device->power_on(now); break;
            case Power::Kind::Reset:
              device->power_off();
              device->power_on(now);
              break;
            case Power::Kind::Cycle:
              device->power_off();
              if (a.off_time.count() == 0) device->power_on(now);
              else undo_.push_back({now + a.off_time, power_on_unless_powered_since(device)});
              break;
          }
        } else if constexpr (std::is_same_v<T, PlantParameter>) {
          auto* plant = world_.plant();
          const auto old = plant->parameter(a.name);
          if (auto err = plant->set_parameter(a.name, a.value); !err.empty()) {
            if (refused) {
              *refused = err;
              return;
            }
            verdicts_.fail("fault " + f.summary, f.mark, now, "plant parameter accepted", err);
            return;
          }
          if (old) {
            const std::string name = a.name;
            const double value = *old;
            clear = [plant, name, value](sim::Time) { plant->set_parameter(name, value); };
          }
        }
      },
      f.action);
  if (refused && refused->empty()) note();
  return clear;
}

void FaultInjector::step(sim::Time now, sim::Duration) {
  // Ends first (in the order they were scheduled), so a fault can be re-applied in the same tick.
  for (std::size_t i = 0; i < undo_.size();) {
    if (undo_[i].due <= now) {
      auto action = std::move(undo_[i].action);
      undo_.erase(undo_.begin() + static_cast<long>(i));
      action(now);
    } else {
      ++i;
    }
  }
  for (auto& s : scheduled_) {
    if (s.fired) continue;
    const bool due = s.spec->at ? now.time_since_epoch() >= *s.spec->at : s.spec->when->holds(s.when.value());
    if (!due) continue;
    s.fired = true;
    apply(*s.spec, now);
  }
}

}  // namespace scenario
