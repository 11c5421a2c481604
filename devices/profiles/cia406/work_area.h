// CiA 406 work area (6400h state, 6401h low limit, 6402h high limit), one area: the state says
// whether the position is inside (00h), above the high limit (02h) or below the low limit (04h).
// Limits are inclusive and compared numerically (no wrap-around); "above" is tested first.
#pragma once

#include <cstdint>

#include "devices/canopen/entry_ref.h"
#include "devices/canopen/object_dictionary.h"

namespace cia406 {

inline constexpr std::uint8_t kWorkAreaInside = 0x00;
inline constexpr std::uint8_t kWorkAreaAbove = 0x02;
inline constexpr std::uint8_t kWorkAreaBelow = 0x04;

std::uint8_t work_area_state(std::int64_t x, std::int64_t low, std::int64_t high);

class WorkArea {
 public:
  static constexpr std::uint16_t kState = 0x6400, kLowLimit = 0x6401, kHighLimit = 0x6402;

  static void add_objects(canopen::ObjectDictionary& od, std::int32_t default_low, std::int32_t default_high);
  void bind(canopen::ObjectDictionary& od);
  /// Evaluates position x and publishes 6400h:01.
  std::uint8_t update(std::int64_t x);

 private:
  // Read in every cycle, so a limit written by SDO or PDO, or reset, acts in the next one.
  canopen::EntryRef<std::uint8_t> state_;
  canopen::EntryRef<std::int32_t> low_, high_;
};

}  // namespace cia406
