// The manufacturer objects the control cycle reads (Trigger, zero points, LVDT gain, the bus
// commands and the tables of the 16 binary sets), each bound once to its entry with the C++ type
// of its fixed CiA type (manufacturer_objects.h). A read is then a load of the entry's bytes, done
// every cycle, so a value written by SDO or RPDO, or put back by a reset, is used in the very next
// cycle as before; nothing is cached between cycles.
#pragma once

#include <array>
#include <cstdint>

#include "devices/canopen/entry_ref.h"
#include "devices/canopen/object_dictionary.h"

namespace vtvpcd {

class CardParameters {
 public:
  static constexpr int kSets = 16;    ///< binary parameter sets k = 0..15
  static constexpr int kGroups = 4;   ///< Contr P/I groups g = 0..3

  /// Binds the entries of a dictionary made by build_dictionary(); throws std::invalid_argument
  /// if one is missing or of another type.
  explicit CardParameters(canopen::ObjectDictionary& od);

  // Raw values (the internal integer format of manual §3.3).
  std::uint32_t trigger() const { return trigger_.get(); }
  std::int32_t zeropoint_pump() const { return zeropoint_pump_.get(); }
  std::int16_t zeropoint_valve() const { return zeropoint_valve_.get(); }
  std::uint16_t gain_lvdt_pump() const { return gain_lvdt_pump_.get(); }
  std::int32_t angle_cmd_bus() const { return angle_cmd_bus_.get(); }
  std::int32_t pressure_cmd_bus() const { return pressure_cmd_bus_.get(); }
  std::int32_t power_cmd_bus() const { return power_cmd_bus_.get(); }
  std::int32_t res_angle_cmd_bus() const { return res_angle_cmd_bus_.get(); }
  std::int32_t angle_cmd_binary(int k) const { return angle_cmd_binary_[static_cast<std::size_t>(k)].get(); }
  std::int32_t press_cmd_binary(int k) const { return press_cmd_binary_[static_cast<std::size_t>(k)].get(); }
  std::int32_t power_cmd_binary(int k) const { return power_cmd_binary_[static_cast<std::size_t>(k)].get(); }
  std::uint16_t angle_ramp_binary(int k) const { return angle_ramp_binary_[static_cast<std::size_t>(k)].get(); }
  std::uint16_t press_ramp_binary(int k) const { return press_ramp_binary_[static_cast<std::size_t>(k)].get(); }
  std::uint16_t contr_p(int g) const { return contr_p_[static_cast<std::size_t>(g)].get(); }
  std::uint16_t contr_i(int g) const { return contr_i_[static_cast<std::size_t>(g)].get(); }

 private:
  canopen::EntryRef<std::uint32_t> trigger_;
  canopen::EntryRef<std::int32_t> zeropoint_pump_;
  canopen::EntryRef<std::int16_t> zeropoint_valve_;
  canopen::EntryRef<std::uint16_t> gain_lvdt_pump_;
  canopen::EntryRef<std::int32_t> angle_cmd_bus_, pressure_cmd_bus_, power_cmd_bus_, res_angle_cmd_bus_;
  std::array<canopen::EntryRef<std::int32_t>, kSets> angle_cmd_binary_, press_cmd_binary_, power_cmd_binary_;
  std::array<canopen::EntryRef<std::uint16_t>, kSets> angle_ramp_binary_, press_ramp_binary_;
  std::array<canopen::EntryRef<std::uint16_t>, kGroups> contr_p_, contr_i_;
};

}  // namespace vtvpcd
