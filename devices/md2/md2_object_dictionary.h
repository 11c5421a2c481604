// The MD2's object dictionary as its manual lists it (§5.4): communication area, node address
// and bit rate, device strings, and per channel the DSP 408 objects; controller-only objects
// exist only on the controller variant.
#pragma once

#include <cstdint>
#include <vector>

#include "devices/canopen/object_dictionary.h"
#include "devices/md2/md2_options.h"

namespace md2 {

constexpr std::uint32_t kDeviceType = 0x10000198;  // as printed (§5.4.4; the text says bit 31)
constexpr int kPdoCount = 8;

canopen::ObjectDictionary build_object_dictionary(const Md2Options& o);

/// Default mapping entries of PDO n (1..4, channel n) for control mode `m` (§2.7.3 of the
/// digest): RPDO = control word + command value, TPDO = status word (+ actual value in the
/// closed-loop modes with an actual-value object).
std::vector<std::uint32_t> default_rpdo_mapping(const Md2Options& o, int channel, std::int8_t m);
std::vector<std::uint32_t> default_tpdo_mapping(const Md2Options& o, int channel, std::int8_t m);

}  // namespace md2
