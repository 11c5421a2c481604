// The run summary's lines about one bus: timing, mean load, error frames, transmit queue
// overflows and the load per COB-ID (the identifiers that occupied the bus most).
#pragma once

#include <string>

#include "sim/bus.h"

namespace scenario {

/// Lines (each starting with four spaces, ending in '\n') for the run summary; `simulated_s`
/// is the run's length.
std::string describe_bus_load(const sim::Bus& bus, double simulated_s, std::size_t top_ids = 8);

}  // namespace scenario
