// CiA 406 linear position arithmetic: magnet position → measuring steps (6501h/6005h:01) →
// code sequence (6000h bit 3, "values fall toward the rod end") → manufacturer offset (650Ah:01)
// and preset offset (650Ch:01). The preset (6010h) makes the output equal the written value.
#pragma once

#include <cstdint>

namespace cia406 {

/// Operating parameters (6000h) bit of a linear encoder.
inline constexpr std::uint16_t kLinearCodeSequenceDecreasing = 0x0008;

struct LinearConfig {
  std::uint32_t step_nm = 100000;  ///< measuring step in nm (6501h): 0.1 mm
  std::int64_t steps = 5000;       ///< measuring length in steps (N); raw counts are 0..N-1
  bool decreasing = false;         ///< 6000h bit 3
  std::int32_t manufacturer_offset = 0;  ///< 650Ah:01
};

/// Steps along the rod for a magnet `metres` from the start of the measuring range, rounded
/// and limited to 0..N-1 (the counting direction is not applied yet).
std::int64_t steps_from_metres(double metres, const LinearConfig& c);
/// The raw count in the output direction: 0..N-1 either way.
std::int64_t directed_raw(std::int64_t steps, const LinearConfig& c);
/// Output position (6020h:01) = raw + manufacturer offset + offset.
std::int64_t linear_position(std::int64_t raw, std::int64_t offset, const LinearConfig& c);
/// Offset (650Ch:01) that makes the output equal `preset` at raw count `raw`.
std::int64_t linear_offset_for_preset(std::int64_t preset, std::int64_t raw, const LinearConfig& c);

}  // namespace cia406
