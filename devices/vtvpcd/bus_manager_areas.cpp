#include "devices/vtvpcd/bus_manager_areas.h"

#include <charconv>

#include "devices/vtvpcd/manufacturer_objects.h"

namespace vtvpcd {

namespace {
constexpr std::size_t kAreaBytes = 32;
constexpr std::size_t kPdoBytes = 8;

std::string hex4(std::uint16_t v) {
  static constexpr char kDigits[] = "0123456789ABCDEF";
  std::string s = "0x";
  for (int shift = 12; shift >= 0; shift -= 4) s += kDigits[(v >> shift) & 0xF];
  return s;
}

bool split(const std::vector<AreaEntry>& area, bool receive, Straddle straddle,
           std::array<std::vector<std::uint32_t>, 4>& out, std::string& error) {
  const char* window = receive ? "to-card (Transmit) area" : "from-card (Receive) area";
  std::size_t pos = 0;
  for (const auto& e : area) {
    const auto* spec = find_object_spec(e.index);
    if (!spec) {
      error = std::string(window) + ": " + hex4(e.index) + " is not a parameter of chapter 4";
      return false;
    }
    if (receive && spec->read_only) {
      error = std::string(window) + ": " + hex4(e.index) + " (" + spec->name + ") is read-only";
      return false;
    }
    if (e.bytes != 2 && e.bytes != 4) {
      error = std::string(window) + ": " + hex4(e.index) + " must be placed as 2 or 4 bytes";
      return false;
    }
    if (pos / kPdoBytes != (pos + e.bytes - 1) / kPdoBytes) {
      if (straddle == Straddle::Reject) {
        error = std::string(window) + ": " + hex4(e.index) + " at byte " + std::to_string(pos) +
                " straddles a PDO boundary";
        return false;
      }
      pos = (pos / kPdoBytes + 1) * kPdoBytes;
    }
    if (pos + e.bytes > kAreaBytes) {
      error = std::string(window) + ": more than 32 bytes";
      return false;
    }
    out[pos / kPdoBytes].push_back(static_cast<std::uint32_t>(e.index) << 16 | static_cast<std::uint32_t>(e.bytes * 8));
    pos += e.bytes;
  }
  return true;
}
}  // namespace

BusManagerAreas BusManagerAreas::manual_example() {
  BusManagerAreas a;
  a.to_card = {{idx::kTrigger, 4}, {idx::kPressureCmdBus, 4}, {idx::kAngleCmdBus, 4}, {idx::kPowerCmdBinary0 + 1, 4}};
  a.from_card = {{idx::kActPressureB, 4}, {idx::kDiscreteOutputs, 4}, {idx::kActValve, 4}};
  return a;
}

bool BusManagerAreas::to_mapping(Mapping& out, std::string& error) const {
  out = Mapping{};
  return split(from_card, false, straddle, out.tpdo, error) && split(to_card, true, straddle, out.rpdo, error);
}

bool parse_area(std::string_view text, std::vector<AreaEntry>& out, std::string& error) {
  out.clear();
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find(',', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view item = text.substr(start, end - start);
    while (!item.empty() && item.front() == ' ') item.remove_prefix(1);
    while (!item.empty() && item.back() == ' ') item.remove_suffix(1);
    const auto colon = item.find(':');
    if (item.empty() || colon == std::string_view::npos) {
      error = "area entry '" + std::string(item) + "' is not index:bytes";
      return false;
    }
    std::string_view index_text = item.substr(0, colon);
    if (index_text.starts_with("0x") || index_text.starts_with("0X")) index_text.remove_prefix(2);
    const std::string_view bytes_text = item.substr(colon + 1);
    unsigned index = 0, bytes = 0;
    const auto r1 = std::from_chars(index_text.data(), index_text.data() + index_text.size(), index, 16);
    const auto r2 = std::from_chars(bytes_text.data(), bytes_text.data() + bytes_text.size(), bytes, 10);
    if (r1.ec != std::errc{} || r1.ptr != index_text.data() + index_text.size() || index > 0xFFFF ||
        r2.ec != std::errc{} || r2.ptr != bytes_text.data() + bytes_text.size() || bytes > 255) {
      error = "area entry '" + std::string(item) + "' is not index:bytes";
      return false;
    }
    out.push_back(AreaEntry{static_cast<std::uint16_t>(index), static_cast<std::uint8_t>(bytes)});
    start = end + 1;
  }
  return true;
}

std::string format_area(const std::vector<AreaEntry>& area) {
  std::string s;
  for (const auto& e : area) {
    if (!s.empty()) s += ',';
    s += hex4(e.index) + ':' + std::to_string(e.bytes);
  }
  return s;
}

}  // namespace vtvpcd
