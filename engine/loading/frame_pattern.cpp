#include "engine/loading/frame_pattern.h"

#include <cstdio>

#include "engine/loading/yaml_fields.h"

namespace scenario {

std::string parse_data_pattern(std::string_view text, FramePattern& p) {
  p.any_data = false;
  p.length = 0;
  p.open_end = false;
  p.value.fill(0);
  p.care.fill(0);
  std::size_t i = 0;
  while (i < text.size()) {
    if (text[i] == ' ' || text[i] == '\t') {
      ++i;
      continue;
    }
    if (p.open_end) return "'*' must be the last item of a data pattern";
    if (text[i] == '*') {
      p.open_end = true;
      ++i;
      continue;
    }
    if (i + 1 >= text.size()) return "'" + std::string(text) + "': bytes are two hex digits or ??";
    if (p.length == 8) return "'" + std::string(text) + "': more than 8 bytes";
    const auto k = static_cast<std::size_t>(p.length);
    if (text[i] == '?' && text[i + 1] == '?') {
      p.care[k] = 0;
    } else {
      const auto v = parse_integer("0x" + std::string(text.substr(i, 2)));
      if (!v) return "'" + std::string(text) + "': '" + std::string(text.substr(i, 2)) + "' is not a hex byte or ??";
      p.value[k] = static_cast<std::uint8_t>(*v);
      p.care[k] = 0xFF;
    }
    ++p.length;
    i += 2;
  }
  return {};
}

std::string FramePattern::describe() const {
  char buf[64];
  std::snprintf(buf, sizeof buf, extended ? "0x%08X" : "0x%03X", id);
  std::string s = buf;
  if (mask != (extended ? 0x1FFFFFFFu : 0x7FFu)) {
    std::snprintf(buf, sizeof buf, "/0x%X", mask);
    s += buf;
  }
  if (!any_data) {
    s += " [";
    for (int i = 0; i < length; ++i) {
      if (care[static_cast<std::size_t>(i)]) {
        std::snprintf(buf, sizeof buf, "%s%02X", i ? " " : "", value[static_cast<std::size_t>(i)]);
      } else {
        std::snprintf(buf, sizeof buf, "%s??", i ? " " : "");
      }
      s += buf;
    }
    if (open_end) s += length ? " *" : "*";
    s += "]";
  }
  return s;
}

}  // namespace scenario
