// Scenario values ↔ CANopen bytes: encodes a literal for an object of a given CiA type (with
// range checks), decodes bytes for messages, and maps the scenario's short type names
// (u8..u64, i8..i64, f32, f64, bool, string, bytes) to CiA data types.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "devices/canopen/data_type.h"
#include "engine/loading/yaml_fields.h"

namespace scenario {

/// nullopt for "bytes" (raw) and unknown names.
std::optional<canopen::DataType> type_from_name(const std::string& name);

/// Encodes `value` as `type` (little-endian); returns an error message ("value 300 out of range
/// for UNSIGNED8"), empty on success.
std::string encode_literal(canopen::DataType type, const Literal& value, std::vector<std::uint8_t>& out);

/// Numeric value of bytes of `type` (strings: NaN).
double decode_number(canopen::DataType type, std::span<const std::uint8_t> bytes);
/// Bytes as text for messages: numbers as numbers (and hex for integers), strings quoted.
std::string describe_bytes(canopen::DataType type, std::span<const std::uint8_t> bytes);
std::string hex_bytes(std::span<const std::uint8_t> bytes);
/// An object's address in messages: "0x6040:00".
std::string object_address(std::uint16_t index, std::uint8_t sub);
/// A 32-bit code in messages (abort codes, mapping entries): "0x06020000".
std::string hex32(std::uint32_t v);

}  // namespace scenario
