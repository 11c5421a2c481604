#include "devices/dsv/dsv_parameters.h"

#include <algorithm>
#include <cmath>

#include "devices/canopen/parameter_store.h"
#include "devices/dsv/control_mode.h"

namespace dsv {

using canopen::OdEntry;
using canopen::Origin;
using canopen::SdoAbort;

namespace {
constexpr std::uint16_t kCurveStoreIndex = DsvParameters::kCurveStoreIndex;
constexpr std::uint8_t kCurveStoreSub = DsvParameters::kCurveStoreFirstSub;
static_assert(DsvParameters::kCurveStoreLastSub == kCurveStoreSub + 2 * 11 - 1);

SdoAbort range(std::int64_t v, std::int64_t lo, std::int64_t hi) {
  if (v > hi) return SdoAbort::ValueTooHigh;
  if (v < lo) return SdoAbort::ValueTooLow;
  return SdoAbort::None;
}
}  // namespace

DsvParameters::DsvParameters(canopen::ObjectDictionary& od, const DsvOptions& options)
    : od_(od),
      o_(options),
      control_mode_(od, 0x6043, 0),
      mode_of_operation_(od, 0x2042, 0),
      characteristic_optimisation_on_(canopen::EntryRef<std::int64_t>::optional(od.entry(0x2344, 1))),
      displayed_unit_(od.entry(0x2202, 0)) {
  for (const auto& spec : application_objects()) {
    OdEntry* e = od.entry(spec.index, 1);
    if (!e) e = od.entry(spec.index, 0);
    if (e) values_.push_back({spec.index, e});
  }
  std::sort(values_.begin(), values_.end(), [](const ValueEntry& a, const ValueEntry& b) { return a.index < b.index; });
  install_rules();
  install_shared();
  install_characteristic_optimisation(0x2344);
  install_characteristic_optimisation(0x23C4);
}

OdEntry& DsvParameters::entry(std::uint16_t index) {
  OdEntry* e = od_.entry(index, 1);
  return e ? *e : *od_.entry(index, 0);
}

OdEntry* DsvParameters::value_entry(std::uint16_t index) const {
  auto it = std::lower_bound(values_.begin(), values_.end(), index,
                             [](const ValueEntry& v, std::uint16_t i) { return v.index < i; });
  if (it != values_.end() && it->index == index) return it->entry;
  OdEntry* e = od_.entry(index, 1);  // not an application object: looked up
  return e ? e : od_.entry(index, 0);
}

std::int64_t DsvParameters::value(std::uint16_t index) const {
  const OdEntry* e = value_entry(index);
  return e ? e->as<std::int64_t>() : 0;
}


std::int64_t DsvParameters::unit_max(std::int8_t m) const {
  const auto unit = displayed_unit_->as<std::int8_t>();
  // §5.4.1 ranges by control mode and 2202h value; 0 = "–" (no such unit in this mode).
  static constexpr std::int64_t kPressure[5] = {500000, 8000000, 1000000, 0, 50000};
  static constexpr std::int64_t kVelocity[5] = {500000, 2000000, 1000000, 100000, 360000};
  static constexpr std::int64_t kPosition[5] = {2000000, 360000, 100000, 0, 0};
  if (unit < 0 || unit > 4) return 0;
  switch (m) {
    case mode::kVprcClosed: return kPressure[unit];
    case mode::kDsc: return kVelocity[unit];
    case mode::kDpc: return kPosition[unit];
    default: return 0;
  }
}

DsvParameters::Scaling DsvParameters::scaling_objects(std::int8_t m) {
  switch (m) {
    case mode::kVprcClosed: return {0x6220, 0x6221, 0x6224, 0x6225};
    case mode::kDsc: return {0x2222, 0x2223, 0x2220, 0x2221};
    default: return {0x6230, 0x6231, 0x6233, 0x6234};
  }
}

SdoAbort DsvParameters::check_rule(const ObjectSpec& s, std::int64_t v, Origin origin, std::span<std::uint8_t> data) {
  const std::int8_t own_mode = static_cast<std::int8_t>(in(s.modes, mode::kVprcClosed) ? mode::kVprcClosed
                                                        : in(s.modes, mode::kDsc)      ? mode::kDsc
                                                                                       : mode::kDpc);
  // A set point from an RPDO cannot be refused: it is limited to its range instead.
  auto limit_or_refuse = [&](std::int64_t lo, std::int64_t hi) {
    if (origin == Origin::Pdo) {
      canopen::encode_unsigned(static_cast<std::uint64_t>(std::clamp(v, lo, hi)), data);
      return SdoAbort::None;
    }
    return range(v, lo, hi);
  };
  switch (s.rule) {
    case Rule::None: return SdoAbort::None;
    case Rule::SignalType: return v == 1 ? SdoAbort::ParameterIncompatible : SdoAbort::None;
    case Rule::CableBreak:
      return v == 1 && od_.get<std::int8_t>(0x2200) != 3 ? SdoAbort::ParameterIncompatible : SdoAbort::None;
    case Rule::DisplayedUnit: {
      const auto m = control_mode();
      const bool dash = (m == mode::kVprcClosed && v == 3) || (m == mode::kDpc && v >= 3);
      return dash ? SdoAbort::ParameterIncompatible : SdoAbort::None;
    }
    case Rule::MeasuringSystem:
      return v == -1 || v == 2 || v == 67 ? SdoAbort::None : SdoAbort::ParameterIncompatible;
    case Rule::RampType: return v == 0 || v == 3 ? SdoAbort::None : SdoAbort::ParameterIncompatible;
    case Rule::WindowType: return v == 0 || v == 2 ? SdoAbort::None : SdoAbort::ParameterIncompatible;
    case Rule::DitherFrequency: {
      static constexpr int kAllowed[] = {20, 25, 30, 35, 40, 45, 50, 55, 60, 70, 80, 100, 125, 165, 250, 500};
      return std::find(std::begin(kAllowed), std::end(kAllowed), v) != std::end(kAllowed) ? SdoAbort::None
                                                                                         : SdoAbort::ParameterIncompatible;
    }
    case Rule::Scaled: return range(v, 0, unit_max(own_mode));
    case Rule::Interface: return range(v, 0, od_.get<std::int8_t>(0x2200) == 0 ? 10000 : 20000);
    case Rule::SetpointToMaxRef: return limit_or_refuse(0, value(scaling_objects(own_mode).max_reference));
    case Rule::PressureSetpoint:
      return control_mode() == mode::kVprcClosed ? limit_or_refuse(0, 16384) : SdoAbort::None;
    case Rule::ModeOfOperation:
      // "If a value will be written which is not possible with the current device" (§5.4.28).
      if (o_.solenoids == 1 && v != 0) return SdoAbort::ValueTooLow;
      if (control_mode() == mode::kDcol && v == 3) return SdoAbort::ValueTooLow;  // 0..2 in mode 6
      return SdoAbort::None;
    case Rule::ErrorHandling: return o_.solenoids == 1 && v >= 2 ? SdoAbort::ValueTooLow : SdoAbort::None;
    case Rule::IminA: return v > shared(Shared::ImaxA) ? SdoAbort::ValueTooHigh : SdoAbort::None;
    case Rule::IminB: return v > shared(Shared::ImaxB) ? SdoAbort::ValueTooHigh : SdoAbort::None;
    case Rule::ImaxA: return v < shared(Shared::IminA) ? SdoAbort::ValueTooLow : SdoAbort::None;
    case Rule::ImaxB: return v < shared(Shared::IminB) ? SdoAbort::ValueTooLow : SdoAbort::None;
  }
  return SdoAbort::None;
}

void DsvParameters::install_rules() {
  for (const auto& spec : application_objects()) {
    const std::uint8_t sub = spec.shape == Shape::Record ? 1 : 0;
    const ObjectSpec* s = &spec;
    if (s->rule != Rule::None) {
      od_.add_check(s->index, sub, [this, s](const OdEntry& e, std::span<std::uint8_t> data, Origin origin) {
        if (origin != Origin::Sdo && origin != Origin::Pdo) return SdoAbort::None;
        return check_rule(*s, canopen::value_as<std::int64_t>(e.type, data), origin, data);
      });
    }
    // A-52 option: written values are truncated to the printed resolution step.
    std::int64_t step = 0;
    switch (s->shared) {
      case Shared::IminA: case Shared::IminB: case Shared::ImaxA: case Shared::ImaxB: step = 16; break;
      case Shared::DeadbandA: case Shared::DeadbandB: case Shared::DitherAmplitude: step = 32; break;
      default: break;
    }
    if (s->index == 0x6480) step = 98;
    if (o_.quantise_on_write && step > 0) {
      od_.add_check(s->index, sub, [step](const OdEntry& e, std::span<std::uint8_t> data, Origin origin) {
        if (origin != Origin::Sdo) return SdoAbort::None;
        const auto v = canopen::value_as<std::int64_t>(e.type, data);
        canopen::encode_unsigned(static_cast<std::uint64_t>(v / step * step), data);
        return SdoAbort::None;
      });
    }
  }
}

void DsvParameters::install_shared() {
  for (const auto& spec : application_objects()) {
    if (spec.shared == Shared::None) continue;
    shared_[static_cast<std::size_t>(spec.shared)].push_back(od_.entry(spec.index, spec.shape == Shape::Record ? 1 : 0));
  }
  for (std::size_t group = 0; group < shared_.size(); ++group)
    shared_first_[group] = canopen::EntryRef<std::int64_t>::optional(shared_[group].empty() ? nullptr : shared_[group].front());
  for (std::size_t group = 1; group < shared_.size(); ++group) {
    for (OdEntry* e : shared_[group]) {
      od_.add_observer(e->index, e->sub, [this, group](OdEntry& written, Origin) {
        const auto v = written.as<std::int64_t>();
        for (OdEntry* other : shared_[group])
          if (other != &written) canopen::EntryRef<std::int64_t>(*other).set(v);
      });
    }
  }
  // The characteristic optimisation of modes 1 and 3 is one parameter set as well.
  for (std::uint8_t sub = 1; sub <= 3; ++sub) {
    for (std::uint16_t index : {std::uint16_t{0x2344}, std::uint16_t{0x23C4}}) {
      const std::uint16_t other = index == 0x2344 ? 0x23C4 : 0x2344;
      od_.add_observer(index, sub, [this, other, sub](OdEntry& written, Origin) {
        canopen::EntryRef<std::int64_t>(*od_.entry(other, sub)).set(written.as<std::int64_t>());
      });
    }
  }
}

void DsvParameters::install_characteristic_optimisation(std::uint16_t index) {
  // Sub 04/05 are a window onto the point [index (sub 03)][solenoid (sub 02)].
  auto point = [this, index]() -> dsp408::CharacteristicCurve::Point& {
    (void)index;
    const auto solenoid = std::min<std::uint16_t>(od_.get<std::uint16_t>(0x2344, 2), 1);
    const auto k = std::clamp<std::uint16_t>(od_.get<std::uint16_t>(0x2344, 3), 1, 11);
    return curves_[solenoid].point(k - 1u);
  };
  od_.add_read_hook(index, 4, [point](OdEntry& e, Origin) {
    canopen::EntryRef<std::int64_t>(e).set(std::llround(point().x * 100));
    return SdoAbort::None;
  });
  od_.add_read_hook(index, 5, [point](OdEntry& e, Origin) {
    canopen::EntryRef<std::int64_t>(e).set(std::llround(point().y * 1000));
    return SdoAbort::None;
  });
  od_.after_write<std::uint16_t>(index, 4, [point](std::uint16_t v, Origin) { point().x = v / 100.0; });
  od_.after_write<std::uint16_t>(index, 5, [point](std::uint16_t v, Origin) { point().y = v / 1000.0; });
}

void DsvParameters::save_curves(canopen::ParameterStore& memory) const {
  for (std::size_t sol = 0; sol < 2; ++sol) {
    for (std::size_t k = 0; k < dsp408::CharacteristicCurve::kPoints; ++k) {
      const auto& p = curves_[sol].point(k);
      const auto x = static_cast<std::uint16_t>(std::llround(p.x * 100)), y = static_cast<std::uint16_t>(std::llround(p.y * 1000));
      memory.put(kCurveStoreIndex, static_cast<std::uint8_t>(kCurveStoreSub + sol * 11 + k),
                 canopen::ParameterStore::Value{false, {static_cast<std::uint8_t>(x), static_cast<std::uint8_t>(x >> 8),
                                                        static_cast<std::uint8_t>(y), static_cast<std::uint8_t>(y >> 8)}});
    }
  }
}

void DsvParameters::load_curves(const canopen::ParameterStore& memory) {
  reset_curves();
  for (std::size_t sol = 0; sol < 2; ++sol) {
    for (std::size_t k = 0; k < dsp408::CharacteristicCurve::kPoints; ++k) {
      const auto* v = memory.find(kCurveStoreIndex, static_cast<std::uint8_t>(kCurveStoreSub + sol * 11 + k));
      if (!v || v->bytes.size() != 4) continue;
      const double x = (v->bytes[0] | v->bytes[1] << 8) / 100.0, y = (v->bytes[2] | v->bytes[3] << 8) / 1000.0;
      curves_[sol].set_point(k, {x, y});
    }
  }
}

void DsvParameters::reset_curves() { curves_ = {}; }

}  // namespace dsv
