#include "devices/profiles/cia406/scripted_input.h"

#include <charconv>
#include <cmath>
#include <numbers>

namespace cia406 {

namespace {
bool parse_double(std::string_view s, double& out) {
  while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
  while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
  if (s.empty()) return false;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), out);
  return r.ec == std::errc() && r.ptr == s.data() + s.size() && std::isfinite(out);
}
}  // namespace

std::string ScriptedInput::parse(std::string_view text) {
  const std::string usage = "expected hold, ramp:RATE or sine:AMPLITUDE,FREQUENCY, got '" + std::string(text) + "'";
  if (text == "hold" || text.empty()) {
    shape_ = Shape::Hold;
    return {};
  }
  if (text.starts_with("ramp:")) {
    double rate = 0;
    if (!parse_double(text.substr(5), rate)) return usage;
    shape_ = Shape::Ramp;
    a_ = rate;
    return {};
  }
  if (text.starts_with("sine:")) {
    const auto args = text.substr(5);
    const auto comma = args.find(',');
    double amp = 0, freq = 0;
    if (comma == std::string_view::npos || !parse_double(args.substr(0, comma), amp) ||
        !parse_double(args.substr(comma + 1), freq) || freq < 0) {
      return usage;
    }
    shape_ = Shape::Sine;
    a_ = amp;
    f_ = freq;
    return {};
  }
  return usage;
}

double ScriptedInput::value(double base, double t) const {
  switch (shape_) {
    case Shape::Hold: return base;
    case Shape::Ramp: return base + a_ * t;
    case Shape::Sine: return base + a_ * std::sin(2 * std::numbers::pi * f_ * t);
  }
  return base;
}

double ScriptedInput::derivative(double t) const {
  switch (shape_) {
    case Shape::Hold: return 0;
    case Shape::Ramp: return a_;
    case Shape::Sine: return a_ * 2 * std::numbers::pi * f_ * std::cos(2 * std::numbers::pi * f_ * t);
  }
  return 0;
}

}  // namespace cia406
