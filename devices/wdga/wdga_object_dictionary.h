// The WDGA's object dictionary, every row of the manual's tables 6.1-6.12 (digest §3): the
// CiA 301 area with heartbeat, 1020h and 1029h, four TPDOs without inhibit time, the manufacturer
// objects 2100h-2504h and the CiA 406 rotary objects including the full CAM unit.
#pragma once

#include <cstdint>

#include "devices/canopen/object_dictionary.h"
#include "devices/wdga/wdga_settings.h"

namespace wdga {

namespace obj {
inline constexpr std::uint16_t kManufacturerStatus = 0x1002, kStore = 0x1010, kRestore = 0x1011;
inline constexpr std::uint16_t kVerifyConfiguration = 0x1020, kErrorBehaviour = 0x1029, kNmtStartup = 0x1F80;
inline constexpr std::uint16_t kBitRate = 0x2100, kNodeId = 0x2101, kBusOffReset = 0x2103;
inline constexpr std::uint16_t kIntegration = 0x2105, kSpeedScaling = 0x2106, kFrequencyLimit = 0x2107;
inline constexpr std::uint16_t kCustomerData = 0x2120, kTemperature = 0x2500;
inline constexpr std::uint16_t kErrorHistory = 0x2502, kAlarmHistory = 0x2503, kWarningHistory = 0x2504;
inline constexpr std::uint16_t kOperatingParameters = 0x6000, kUnitsPerRevolution = 0x6001, kTotalRange = 0x6002;
inline constexpr std::uint16_t kPreset = 0x6003, kPosition = 0x6004, kPositionHigh = 0x6008, kPresetHigh = 0x6009;
inline constexpr std::uint16_t kSpeed = 0x6030, kAcceleration = 0x6040, kJerk = 0x6050, kCyclicTimer = 0x6200;
inline constexpr std::uint16_t kOperatingStatus = 0x6500, kAlarms = 0x6503, kWarnings = 0x6505, kOffset = 0x6509;
inline constexpr std::uint16_t kModuleIdentification = 0x650A;
}  // namespace obj

inline constexpr std::uint32_t kVendorId = 0x0100021F;
inline constexpr std::uint32_t kProductCode = 0x57444741;  // "WDGA"
inline constexpr std::uint32_t kPhysicalResolution = 16384;
inline constexpr std::uint64_t kPhysicalRevolutions = 1ull << 39;

canopen::ObjectDictionary make_object_dictionary(const Settings& s);

}  // namespace wdga
