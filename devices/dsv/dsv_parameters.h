// The DSV's parameter objects at work: the value rules of the manual and the digest beyond the
// static ranges (enumerations, Imin/Imax cross-checks, unit-dependent ranges, hardware-dependent
// values), the parameters shared by several indices, the characteristic optimisation's selector
// access, and typed reads of what the signal chain needs.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "devices/canopen/entry_ref.h"
#include "devices/canopen/object_dictionary.h"
#include "devices/canopen/parameter_store.h"
#include "devices/dsv/dsv_objects.h"
#include "devices/dsv/dsv_options.h"
#include "devices/profiles/dsp408/characteristic_curve.h"

namespace dsv {

class DsvParameters {
 public:
  DsvParameters(canopen::ObjectDictionary& od, const DsvOptions& options);
  DsvParameters(const DsvParameters&) = delete;
  DsvParameters& operator=(const DsvParameters&) = delete;

  std::int8_t control_mode() const { return control_mode_.get(); }
  std::int8_t mode_of_operation() const { return mode_of_operation_.get(); }
  /// Value of a shared parameter (all its indices hold the same value).
  std::int64_t shared(Shared s) const { return shared_first_[static_cast<std::size_t>(s)].get(); }
  /// Value (sub 1 of a record, sub 0 of a VAR) of an application object.
  std::int64_t value(std::uint16_t index) const;
  /// The entry value() reads (null when there is none): for code that binds it once.
  canopen::OdEntry* value_entry(std::uint16_t index) const;
  /// The same entry bound for per-cycle reads (unbound when there is none): value() without the lookup.
  canopen::EntryRef<std::int64_t> bind_value(std::uint16_t index) const { return canopen::EntryRef<std::int64_t>::optional(value_entry(index)); }
  canopen::OdEntry& entry(std::uint16_t index);

  /// Maximum raw value of the unit selected by 2202h for closed-loop mode `m` (0 = "–").
  std::int64_t unit_max(std::int8_t m) const;
  /// Min/max reference and interface objects of closed-loop mode `m`.
  struct Scaling {
    std::uint16_t min_reference, max_reference, min_interface, max_interface;
  };
  static Scaling scaling_objects(std::int8_t m);

  dsp408::CharacteristicCurve& curve(int solenoid) { return curves_[static_cast<std::size_t>(solenoid)]; }
  bool characteristic_on() const { return static_cast<std::uint16_t>(characteristic_optimisation_on_.get()) == 1; }
  /// Characteristic points in the store (pseudo sub-indices of 0x2344 ≥ 0x10, saved with the
  /// application group): into / out of the curves.
  void save_curves(canopen::ParameterStore& memory) const;
  /// The pseudo sub-indices save_curves() uses (index 0x2344): the store leaves them to the DSV.
  static constexpr std::uint16_t kCurveStoreIndex = 0x2344;
  static constexpr std::uint8_t kCurveStoreFirstSub = 0x10, kCurveStoreLastSub = 0x25;  // 11 points × 2 solenoids
  void load_curves(const canopen::ParameterStore& memory);
  void reset_curves();

 private:
  void install_rules();
  void install_shared();
  void install_characteristic_optimisation(std::uint16_t index);
  canopen::SdoAbort check_rule(const ObjectSpec& s, std::int64_t v, canopen::Origin origin, std::span<std::uint8_t> data);

  canopen::ObjectDictionary& od_;
  const DsvOptions& o_;
  canopen::EntryRef<std::int8_t> control_mode_;
  canopen::EntryRef<std::int8_t> mode_of_operation_;
  canopen::EntryRef<std::int64_t> characteristic_optimisation_on_;  // 0x2344:01
  canopen::OdEntry* displayed_unit_;               // 0x2202
  // Every application object's index → the entry value() reads (sub 1 of a record, else sub 0),
  // sorted by index, bound when built: a binary search instead of two map walks.
  struct ValueEntry {
    std::uint16_t index;
    canopen::OdEntry* entry;
  };
  std::vector<ValueEntry> values_;
  std::array<std::vector<canopen::OdEntry*>, 17> shared_{};
  std::array<canopen::EntryRef<std::int64_t>, 17> shared_first_{};  // the entry shared() reads
  std::array<dsp408::CharacteristicCurve, 2> curves_;
};

}  // namespace dsv
