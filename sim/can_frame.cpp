#include "sim/can_frame.h"

#include <algorithm>
#include <cstring>

namespace sim {

CanFrame CanFrame::data_frame(std::uint32_t id, std::initializer_list<std::uint8_t> bytes) {
  return data_frame(id, std::span<const std::uint8_t>(bytes.begin(), bytes.size()));
}

CanFrame CanFrame::data_frame(std::uint32_t id, std::span<const std::uint8_t> bytes) {
  CanFrame f;
  f.id = id;
  f.extended = id > kMaxStdId;
  f.dlc = static_cast<std::uint8_t>(std::min<std::size_t>(bytes.size(), 8));
  std::copy_n(bytes.begin(), f.dlc, f.data.begin());
  return f;
}

CanFrame CanFrame::remote_frame(std::uint32_t id, std::uint8_t dlc) {
  CanFrame f;
  f.id = id;
  f.extended = id > kMaxStdId;
  f.rtr = true;
  f.dlc = std::min<std::uint8_t>(dlc, 8);
  return f;
}

bool CanFrame::operator==(const CanFrame& o) const {
  if (id != o.id || dlc != o.dlc || extended != o.extended || rtr != o.rtr) return false;
  return rtr || std::equal(data.begin(), data.begin() + dlc, o.data.begin());
}

std::size_t format_candump(const CanFrame& f, char* out) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  std::size_t n = 0;
  const int id_digits = f.extended ? 8 : 3;
  for (int i = id_digits - 1; i >= 0; --i) out[n++] = kHex[(f.id >> (4 * i)) & 0xF];
  out[n++] = '#';
  if (f.rtr) {
    out[n++] = 'R';
    if (f.dlc > 0) out[n++] = kHex[f.dlc];
  } else {
    for (int i = 0; i < f.dlc && i < 8; ++i) {
      out[n++] = kHex[f.data[i] >> 4];
      out[n++] = kHex[f.data[i] & 0xF];
    }
  }
  out[n] = '\0';
  return n;
}

std::string to_candump(const CanFrame& f) {
  char buf[kCandumpMax];
  return std::string(buf, format_candump(f, buf));
}

namespace {
int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}
}  // namespace

std::optional<CanFrame> parse_candump(std::string_view text) {
  const auto hash = text.find('#');
  if (hash == std::string_view::npos || hash == 0) return std::nullopt;
  const auto id_text = text.substr(0, hash);
  if (id_text.size() != 3 && id_text.size() != 8) return std::nullopt;
  std::uint32_t id = 0;
  for (char c : id_text) {
    const int v = hex_value(c);
    if (v < 0) return std::nullopt;
    id = (id << 4) | static_cast<std::uint32_t>(v);
  }
  CanFrame f;
  f.id = id;
  f.extended = id_text.size() == 8;
  if (f.extended ? id > CanFrame::kMaxExtId : id > CanFrame::kMaxStdId) return std::nullopt;
  auto rest = text.substr(hash + 1);
  if (!rest.empty() && (rest[0] == 'R' || rest[0] == 'r')) {
    f.rtr = true;
    if (rest.size() == 1) return f;
    if (rest.size() != 2) return std::nullopt;
    const int v = hex_value(rest[1]);
    if (v < 0 || v > 8) return std::nullopt;
    f.dlc = static_cast<std::uint8_t>(v);
    return f;
  }
  // can-utils allows '.' separators between bytes.
  std::size_t n = 0;
  for (std::size_t i = 0; i < rest.size();) {
    if (rest[i] == '.') { ++i; continue; }
    if (i + 1 >= rest.size() || n >= 8) return std::nullopt;
    const int hi = hex_value(rest[i]), lo = hex_value(rest[i + 1]);
    if (hi < 0 || lo < 0) return std::nullopt;
    f.data[n++] = static_cast<std::uint8_t>((hi << 4) | lo);
    i += 2;
  }
  f.dlc = static_cast<std::uint8_t>(n);
  return f;
}

}  // namespace sim
