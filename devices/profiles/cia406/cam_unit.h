// CiA 406 CAM unit, one channel of up to 8 cams (6300h state, 6301h enable, 6302h polarity,
// 6310h+k low limit, 6320h+k high limit, 6330h+k hysteresis). A cam is inside when
// low ≤ x ≤ high; once inside it stays inside while low − h ≤ x ≤ high + h, so the switch
// points lag by the hysteresis in the direction of travel. State bit k = enabled and
// (inside xor inverted).
#pragma once

#include <array>
#include <cstdint>

#include "devices/canopen/entry_ref.h"
#include "devices/canopen/object_dictionary.h"

namespace cia406 {

struct Cam {
  std::int64_t low = 0;
  std::int64_t high = 0;
  std::uint64_t hysteresis = 0;
  bool inside = false;  ///< switching memory (kept whether enabled or not)

  /// Updates the switching memory for position x; returns it.
  bool update(std::int64_t x);
};

class CamUnit {
 public:
  static constexpr int kCams = 8;
  static constexpr std::uint16_t kState = 0x6300, kEnable = 0x6301, kPolarity = 0x6302;
  static constexpr std::uint16_t kLowLimit = 0x6310, kHighLimit = 0x6320, kHysteresis = 0x6330;

  /// Adds the channel-1 objects 6300h..6337h with their CiA 406 types and zero defaults.
  static void add_objects(canopen::ObjectDictionary& od);
  /// Binds the entries (of the types add_objects() gives them; throws std::invalid_argument for
  /// others) and installs the write rule for low limits: a changed low limit must stay below the
  /// cam's high limit (else `abort`); rewriting the current value is accepted.
  void bind(canopen::ObjectDictionary& od, canopen::SdoAbort abort = canopen::SdoAbort::MaxLessThanMin);
  /// Forgets the switching memory (power-on).
  void reset();
  /// Evaluates every cam at position x and publishes 6300h:01; returns the state byte.
  std::uint8_t update(std::int64_t x);

 private:
  std::array<bool, kCams> inside_{};  ///< the cams' switching memories (kept whether enabled or not)
  // Read in every cycle, so a limit written by SDO or PDO, or reset, acts in the next one.
  canopen::EntryRef<std::uint8_t> state_, enable_, polarity_;
  std::array<canopen::EntryRef<std::int32_t>, kCams> low_{}, high_{};
  std::array<canopen::EntryRef<std::uint32_t>, kCams> hysteresis_{};
};

}  // namespace cia406
