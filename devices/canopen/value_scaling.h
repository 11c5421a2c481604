// A product's documented scaling of one dictionary value: how its raw counts read in engineering
// units (6020h:01 of the HLT 1100 in steps of 0.1 mm, a DSP 408 set-point of ±16384 = ±100 %).
// Each product keeps its own table (devices/<product>/); the API and the frame decoder only read it.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace canopen {

struct ValueScaling {
  std::string_view unit;  ///< "" = no documented scaling; otherwise a literal ("mm", "%", "turns")
  double scale = 1.0;     ///< engineering value = raw × scale + offset
  double offset = 0.0;
  int decimals = 0;       ///< digits after the point the resolution carries

  explicit operator bool() const { return !unit.empty(); }
  double apply(double raw) const { return raw * scale + offset; }
};

/// Digits after the point needed to show one `step` (0.1 → 1, 0.0061 → 4, 1 → 0), at most 6.
int decimals_for(double step);
/// A scaling whose decimals follow its step: `scaled(unit, scale)` for "raw × scale in unit".
ValueScaling scaled(std::string_view unit, double scale, double offset = 0.0);
/// "12.3 mm" (the raw value scaled, with the scaling's decimals); "" without a scaling.
std::string scaled_text(double raw, const ValueScaling& s);

}  // namespace canopen
