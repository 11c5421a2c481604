// How the VT-VPCD speaks CANopen where the manual (or, where it is silent, the digest's [R]
// reading) differs from the CiA 301 defaults of the shared stack: the NodePolicy knobs, and the
// object-dictionary rules for the PDO parameters (identifiers and mapping only in
// Pre-operational, transmission types 0xFE/0xFF, mapping entries of 16 or 32 bits, aborts from the
// manual's table only).
#pragma once

#include "devices/canopen/node.h"
#include "devices/canopen/node_policy.h"
#include "devices/vtvpcd/settings.h"

namespace vtvpcd {

canopen::NodePolicy make_policy(const Settings& settings);

/// Installs the product's checks on the communication objects of `node` (after the stack bound
/// its own, so the stack's run first).
void install_communication_rules(canopen::Node& node, const Settings& settings);

}  // namespace vtvpcd
