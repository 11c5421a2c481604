// The API's JSON shapes (docs/api.md) for what the scheduler published: nodes, frames, EMCY.
#pragma once

#include <nlohmann/json.hpp>

#include <functional>
#include <string>
#include <string_view>

#include "control/live_state.h"
#include "devices/canopen/frame_decoder.h"
#include "sim/display_unit.h"

namespace control {

/// "INITIALISING", "PRE-OPERATIONAL", "OPERATIONAL", "STOPPED", or "OFF" when unpowered.
std::string nmt_name(const NodeStatus& s);
/// Node = {"name","node_id","bus","nmt","error_register","device":{...},"emcy":[...]}.
/// A node's EMCY code in its product's words ("" when its manual gives none).
using EmcyMeaning = std::function<std::string_view(std::uint16_t code)>;
nlohmann::json node_json(const std::string& name, const std::string& bus, const NodeStatus& s, const EmcyMeaning& meaning);
/// Frame = {"t_us","bus","id","ext","rtr","dlc","data","bytes","dir","service","node","text","candump"}
/// ("data" "2B40600007000000", "bytes" the same spaced: "2B 40 60 00 07 00 00 00").
nlohmann::json frame_json(const CapturedFrame& f, const std::string& bus, const canopen::DecodedFrame& d);
/// Signal = {"name","unit" (SI),"display_unit","display_scale","display_offset","display_span"}:
/// display = si × scale + offset; a plot's axis spans at least display_span (0: any).
nlohmann::json signal_json(const std::string& name, const std::string& unit, const sim::DisplayUnit& display);
std::string hex_string(const std::uint8_t* data, std::size_t n);
/// A dictionary value as JSON: numbers for numeric types, text for visible strings, hex else.
nlohmann::json value_json(canopen::DataType type, const std::vector<std::uint8_t>& bytes);
/// An integer entry in the product's documented unit ("12.3 mm"); "" without a scaling.
std::string display_text(canopen::DataType type, const std::vector<std::uint8_t>& bytes, const canopen::ValueScaling& s);
/// Parses "0F00" / "0f 00" into bytes; false if malformed (odd digits, non-hex, > max bytes).
bool parse_hex(const std::string& text, std::vector<std::uint8_t>& out, std::size_t max_bytes);

}  // namespace control
