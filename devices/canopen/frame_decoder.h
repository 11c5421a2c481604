// Decodes a CAN frame as a CANopen engineer reads it (CiA 301 / CiA 305): NMT command and target,
// SYNC with counter, TIME, EMCY with the code's meaning and the error-register bits, SDO requests
// and responses with index:sub, the object's name, segment toggles and abort texts, PDOs with
// their mapped objects' names and values, heartbeat, boot-up and node guarding with the state's
// name, LSS, the heartbeat consumer times of 1016h, the products' own EMCY codes, process values
// in the product's documented units. Pure: what it knows of the nodes (names, types, PDO mappings) comes from a context.
// Shared by the live control plane's trace, trace export and reports.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "devices/canopen/data_type.h"
#include "devices/canopen/value_scaling.h"
#include "sim/can_frame.h"

namespace canopen {

enum class Service : std::uint8_t { Nmt, Sync, Emcy, Time, Tpdo, Rpdo, SdoRx, SdoTx, Heartbeat, Lss, Other };

/// "NMT", "SYNC", "EMCY", "TIME", "TPDO1".."TPDO4" / "RPDO1".., "SDO_RX", "SDO_TX", "HEARTBEAT",
/// "LSS", "OTHER". `pdo` is the PDO number (TPDO/RPDO only; 0 prints "TPDO").
std::string service_name(Service s, int pdo);

/// What the decoder may know of the nodes on the bus. The default knows nothing (frames are
/// decoded by the pre-defined connection set alone).
class DecoderContext {
 public:
  struct ObjectInfo {
    std::string_view name;
    DataType type = DataType::Unsigned32;
    ValueScaling scaling;  ///< the product's documented scaling (PDO/SDO values print in its unit)
  };
  struct MappedEntry {
    std::uint16_t index = 0;
    std::uint8_t sub = 0;
    std::uint8_t bits = 0;
  };
  struct PdoInfo {
    std::uint8_t node = 0;
    bool transmit = true;  ///< the node's TPDO (else its RPDO)
    int number = 0;        ///< 1-based
    std::vector<MappedEntry> entries;
  };
  virtual ~DecoderContext() = default;
  /// The entry in node `node`'s dictionary, or nullptr.
  virtual const ObjectInfo* object(std::uint8_t node, std::uint16_t index, std::uint8_t sub) const;
  /// The PDO some node sends or receives on `cob_id`, or nullptr.
  virtual const PdoInfo* pdo(std::uint32_t cob_id) const;
  /// The product's own meaning of EMCY code `code` sent by node `node` (manufacturer codes of its
  /// manual), or "" (then the CiA 301 meaning of the code or its class is printed).
  virtual std::string_view emcy_text(std::uint8_t node, std::uint16_t code) const;
};

struct DecodedFrame {
  Service service = Service::Other;
  int pdo = 0;     ///< TPDO/RPDO number
  int node = -1;   ///< the node the frame concerns (sender or addressee); -1 none, 0 all (NMT)
  std::string text;
};

DecodedFrame decode_frame(const sim::CanFrame& frame, const DecoderContext& context);
DecodedFrame decode_frame(const sim::CanFrame& frame);

/// Data bytes as spaced hex: "2B 40 60 00 0F 00 00 00".
std::string spaced_hex(const std::uint8_t* data, std::size_t n);
/// A heartbeat consumer entry (1016h:01..7F): "node 5, 500 ms"; "off" when the node-ID or the time is 0.
std::string heartbeat_consumer_text(std::uint32_t value);

/// CiA 301 emergency error code meaning (exact code, else its class), e.g. 0x8130 →
/// "life guard or heartbeat error"; 0xFFxx "device specific".
std::string_view emcy_code_text(std::uint16_t code);
/// Error register (0x1001) bits by name, e.g. 0x11 → "generic, communication"; 0 → "none".
std::string error_register_text(std::uint8_t reg);
/// NMT state byte of heartbeat/guarding (without the toggle bit): "BOOT-UP", "STOPPED", ...
std::string_view nmt_state_text(std::uint8_t state);
/// NMT command specifier, by its word (nmt_state.h): "start", "stop", "pre_operational",
/// "reset_node", "reset_communication"; else "unknown command".
std::string_view nmt_command_text(std::uint8_t command);

}  // namespace canopen
