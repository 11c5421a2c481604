// The HLT 1100's object dictionary, exactly the objects of the manual (digest §3): the CiA 301
// communication area without heartbeat, EMCY COB-ID or 0x1029, two fixed TPDOs on 6020h:01, and
// the CiA 406 linear-encoder objects. Anything not listed aborts with 0x06020000.
#pragma once

#include <cstdint>

#include "devices/canopen/object_dictionary.h"
#include "devices/hlt1100/hlt1100_settings.h"

namespace hlt1100 {

namespace obj {
inline constexpr std::uint16_t kErrorRegister = 0x1001, kErrorField = 0x1003, kStore = 0x1010;
inline constexpr std::uint16_t kTpdo1 = 0x1800, kTpdo2 = 0x1801, kNmtStartup = 0x1F80;
inline constexpr std::uint16_t kOperatingParameters = 0x6000, kMeasuringStepSettings = 0x6005;
inline constexpr std::uint16_t kPreset = 0x6010, kPosition = 0x6020, kSpeed = 0x6030, kCyclicTimer = 0x6200;
inline constexpr std::uint16_t kOperatingStatus = 0x6500, kMeasuringStep = 0x6501, kAlarms = 0x6503;
inline constexpr std::uint16_t kSupportedAlarms = 0x6504, kOffset = 0x650C;
}  // namespace obj

inline constexpr std::uint32_t kDeviceType = 0x000A0196;
inline constexpr std::uint32_t kVendorId = 0x000000DA;
inline constexpr std::uint32_t kPositionMapping = 0x60200120;
inline constexpr std::uint32_t kSpeedMapping = 0x60300110;

canopen::ObjectDictionary make_object_dictionary(const Settings& s);

}  // namespace hlt1100
