// The API's JSON shapes (docs/api.md) for what the scheduler published: nodes, frames, EMCY.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

#include "control/live_state.h"
#include "devices/canopen/frame_decoder.h"

namespace control {

/// "INITIALISING", "PRE-OPERATIONAL", "OPERATIONAL", "STOPPED", or "OFF" when unpowered.
std::string nmt_name(const NodeStatus& s);
/// Node = {"name","node_id","bus","nmt","error_register","device":{...},"emcy":[...]}.
nlohmann::json node_json(const std::string& name, const std::string& bus, const NodeStatus& s);
/// Frame = {"t_us","bus","id","ext","rtr","dlc","data","dir","service","node","text","candump"}.
nlohmann::json frame_json(const CapturedFrame& f, const std::string& bus, const canopen::DecodedFrame& d);
std::string hex_string(const std::uint8_t* data, std::size_t n);
/// A dictionary value as JSON: numbers for numeric types, text for visible strings, hex else.
nlohmann::json value_json(canopen::DataType type, const std::vector<std::uint8_t>& bytes);
/// Parses "0F00" / "0f 00" into bytes; false if malformed (odd digits, non-hex, > max bytes).
bool parse_hex(const std::string& text, std::vector<std::uint8_t>& out, std::size_t max_bytes);

}  // namespace control
