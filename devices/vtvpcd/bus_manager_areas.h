// The two 32-byte areas of BODAC's Bus Manager (manual §3.4, "Example of a PDO configuration"):
// the parameters the card sends (window "Receive", master's view) and the ones it receives
// (window "Transmit"), in transmission order, each placed as 2 or 4 bytes. The card keeps them in
// flash; this emulator takes them from its configuration and turns them into DS-301 PDO mappings:
// area bytes 0-7 -> PDO1, 8-15 -> PDO2, 16-23 -> PDO3, 24-31 -> PDO4 (digest A16).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace vtvpcd {

struct AreaEntry {
  std::uint16_t index = 0;
  std::uint8_t bytes = 4;  ///< 2 or 4
  bool operator==(const AreaEntry&) const = default;
};

/// An entry that would straddle an 8-byte PDO boundary: refuse the image, or start it in the
/// next PDO (the bytes left over are not sent).
enum class Straddle : std::uint8_t { Reject, Pad };

struct BusManagerAreas {
  std::vector<AreaEntry> from_card;  ///< "Receive" window -> TPDO1..4
  std::vector<AreaEntry> to_card;    ///< "Transmit" window -> RPDO1..4
  Straddle straddle = Straddle::Reject;

  /// The manual's example: to the card Trigger, Pressure CMD (BUS), Angle CMD (BUS), Power CMD
  /// binary 1 (4 bytes each); from the card act. pressure B, Discrete Outputs, act. valve.
  static BusManagerAreas manual_example();

  /// DS-301 mapping words (index << 16 | sub << 8 | bits) of PDO 1..4 per direction.
  struct Mapping {
    std::array<std::vector<std::uint32_t>, 4> tpdo;
    std::array<std::vector<std::uint32_t>, 4> rpdo;
  };
  /// Splits the areas into PDOs; false with `error` if an entry names no chapter-4 object, puts
  /// a read-only object into the receive area, has a width other than 2/4, overflows 32 bytes or
  /// straddles a PDO boundary under Straddle::Reject.
  bool to_mapping(Mapping& out, std::string& error) const;
};

/// Parses "0x2F0F:4,0x2F26:4" (index:bytes, comma-separated; "" = empty area).
bool parse_area(std::string_view text, std::vector<AreaEntry>& out, std::string& error);
std::string format_area(const std::vector<AreaEntry>& area);

}  // namespace vtvpcd
