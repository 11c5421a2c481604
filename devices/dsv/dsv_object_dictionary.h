// The DSV's object dictionary (§5.4): communication area with its two fixed PDOs, node address,
// bit rate, temperature, device control, strings and the application objects of every control
// mode (which of them answer depends on 6043h, see DsvDevice).
#pragma once

#include <cstdint>
#include <vector>

#include "devices/canopen/object_dictionary.h"
#include "devices/dsv/dsv_options.h"

namespace dsv {

constexpr std::uint32_t kDeviceType = 0x00000198;  // §5.4.4: bit 31 = 0, not modular

canopen::ObjectDictionary build_object_dictionary(const DsvOptions& o);

/// The fixed PDO set of a control mode and mode of operation (§5.4.16/§5.4.18, digest table 2.7).
struct PdoSet {
  int active_rpdo = 1;  ///< 1 or 2
  int active_tpdo = 1;
  std::vector<std::uint32_t> rpdo1, rpdo2, tpdo1, tpdo2;  ///< mapping entries as read back
};
PdoSet pdo_set(std::int8_t control_mode, std::int8_t mode_of_operation, bool m4_six_bytes);

}  // namespace dsv
