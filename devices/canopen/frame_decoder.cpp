#include "devices/canopen/frame_decoder.h"

#include <cstdio>
#include <cstring>

#include "devices/canopen/nmt_command.h"
#include "devices/canopen/sdo_abort.h"

namespace canopen {

namespace {

std::string hex(std::uint64_t v, int digits) {
  char buf[24];
  std::snprintf(buf, sizeof buf, "0x%0*llX", digits, static_cast<unsigned long long>(v));
  return buf;
}

std::string index_sub(std::uint16_t index, std::uint8_t sub) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%04X:%02X", index, sub);
  return buf;
}

std::uint32_t le(const sim::CanFrame& f, int at, int n) {
  std::uint32_t v = 0;
  for (int i = n - 1; i >= 0; --i) v = (v << 8) | f.data[static_cast<std::size_t>(at + i)];
  return v;
}

std::string bytes_hex(const sim::CanFrame& f, int from, int to) {
  if (to > f.dlc) to = f.dlc;
  if (from >= to) return {};
  return spaced_hex(f.data.data() + from, static_cast<std::size_t>(to - from));
}

/// An object reference with its name when the context knows it: "6040:00 Device control word".
std::string object_text(const DecoderContext& ctx, std::uint8_t node, std::uint16_t index, std::uint8_t sub,
                        const DecoderContext::ObjectInfo** info = nullptr) {
  std::string s = index_sub(index, sub);
  const auto* o = ctx.object(node, index, sub);
  if (info) *info = o;
  if (o && !o->name.empty()) {
    s += ' ';
    s += o->name;
  }
  return s;
}

/// A little-endian value of `bits` bits as its type reads (hex and decimal for integers); with the
/// product's scaling, the value in its unit first ("12.3 mm (raw 123)").
std::string value_text(std::uint64_t raw, int bits, const DecoderContext::ObjectInfo* info) {
  const DataType type = info ? info->type : DataType::Unsigned32;
  if (info && info->scaling && (is_signed_integer(type) || is_unsigned_integer(type)) && bits > 0 && bits <= 64) {
    double v = static_cast<double>(raw);
    if (is_signed_integer(type) && bits < 64 && (raw >> (bits - 1)) & 1)
      v = static_cast<double>(static_cast<std::int64_t>(raw | (~0ULL << bits)));
    else if (is_signed_integer(type) && bits == 64)
      v = static_cast<double>(static_cast<std::int64_t>(raw));
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.0f", v);
    return scaled_text(v, info->scaling) + " (raw " + buf + ")";
  }
  if (type == DataType::Real32 && bits == 32) {
    float f;
    const auto u = static_cast<std::uint32_t>(raw);
    std::memcpy(&f, &u, 4);
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", static_cast<double>(f));
    return buf;
  }
  if (type == DataType::Boolean) return raw ? "TRUE" : "FALSE";
  std::string s = hex(raw, (bits + 3) / 4);
  if (is_signed_integer(type) && bits > 0 && bits < 64 && (raw >> (bits - 1)) & 1) {
    const auto v = static_cast<std::int64_t>(raw | (~0ULL << bits));
    s += " (" + std::to_string(v) + ")";
  } else if (is_signed_integer(type) || is_unsigned_integer(type)) {
    s += " (" + std::to_string(raw) + ")";
  }
  return s;
}

/// An expedited SDO value: 1016h entries as consumer node-ID and time, else as the type reads.
std::string expedited_text(std::uint16_t index, std::uint8_t sub, std::uint32_t value, int n,
                           const DecoderContext::ObjectInfo* info) {
  if (index == 0x1016 && sub >= 1 && n == 4) return heartbeat_consumer_text(value) + " (" + hex(value, 8) + ")";
  return value_text(value, n * 8, info);
}

void decode_sdo(const sim::CanFrame& f, bool request, const DecoderContext& ctx, DecodedFrame& d) {
  const auto node = static_cast<std::uint8_t>(f.id & 0x7F);
  if (f.dlc < 1) {
    d.text = "SDO (empty frame)";
    return;
  }
  const std::uint8_t b0 = f.data[0];
  const int cs = b0 >> 5;
  const bool has_mux = f.dlc >= 4;
  const auto index = static_cast<std::uint16_t>(le(f, 1, 2));
  const auto sub = f.data[3];
  const auto toggle = [&] { return std::string(" toggle ") + ((b0 & 0x10) ? "1" : "0"); };
  const auto segment = [&](bool more_bit_set) {
    const int unused = (b0 >> 1) & 7;
    std::string s = toggle() + ", " + std::to_string(7 - unused) + " bytes";
    if (7 - unused > 0) s += " [" + bytes_hex(f, 1, 8 - unused) + "]";
    if (more_bit_set) s += ", last";
    return s;
  };
  if (cs == 4) {  // abort, both directions
    const std::uint32_t code = f.dlc >= 8 ? le(f, 4, 4) : 0;
    d.text = std::string("SDO abort ") + (has_mux ? object_text(ctx, node, index, sub) : "") + ": " + hex(code, 8) + " " +
             std::string(describe(static_cast<SdoAbort>(code)));
    return;
  }
  if (request) {
    switch (cs) {
      case 1: {  // initiate download
        const DecoderContext::ObjectInfo* info = nullptr;
        const std::string obj = object_text(ctx, node, index, sub, &info);
        if (b0 & 0x02) {
          const int n = (b0 & 0x01) ? 4 - ((b0 >> 2) & 3) : 4;
          d.text = "SDO download " + obj + " = " + expedited_text(index, sub, le(f, 4, n), n, info);
        } else {
          d.text = "SDO download initiate " + obj + ((b0 & 0x01) ? ", " + std::to_string(le(f, 4, 4)) + " bytes" : "");
        }
        return;
      }
      case 0: d.text = "SDO download segment" + segment(b0 & 0x01); return;
      case 2: d.text = "SDO upload request " + object_text(ctx, node, index, sub); return;
      case 3: d.text = "SDO upload segment request" + toggle(); return;
      case 5: d.text = "SDO block upload " + std::string(has_mux ? object_text(ctx, node, index, sub) : ""); return;
      case 6: d.text = "SDO block download " + std::string(has_mux ? object_text(ctx, node, index, sub) : ""); return;
      default: d.text = "SDO request with unknown command " + hex(b0, 2); return;
    }
  }
  switch (cs) {
    case 3: d.text = "SDO download response " + object_text(ctx, node, index, sub) + ": done"; return;
    case 1: d.text = "SDO download segment response" + toggle(); return;
    case 2: {
      const DecoderContext::ObjectInfo* info = nullptr;
      const std::string obj = object_text(ctx, node, index, sub, &info);
      if (b0 & 0x02) {
        const int n = (b0 & 0x01) ? 4 - ((b0 >> 2) & 3) : 4;
        d.text = "SDO upload response " + obj + " = " + expedited_text(index, sub, le(f, 4, n), n, info);
      } else {
        d.text = "SDO upload initiate response " + obj + ((b0 & 0x01) ? ", " + std::to_string(le(f, 4, 4)) + " bytes" : "");
      }
      return;
    }
    case 0: d.text = "SDO upload segment response" + segment(b0 & 0x01); return;
    case 5: d.text = "SDO block download response"; return;
    case 6: d.text = "SDO block upload response"; return;
    default: d.text = "SDO response with unknown command " + hex(b0, 2); return;
  }
}

std::string_view lss_command_text(std::uint8_t cs) {
  switch (cs) {
    case 0x04: return "switch state global";
    case 0x11: return "configure node-ID";
    case 0x13: return "configure bit timing";
    case 0x15: return "activate bit timing";
    case 0x17: return "store configuration";
    case 0x40: return "switch state selective: vendor-ID";
    case 0x41: return "switch state selective: product code";
    case 0x42: return "switch state selective: revision number";
    case 0x43: return "switch state selective: serial number";
    case 0x44: return "switch state selective response";
    case 0x46: return "identify remote slave: vendor-ID";
    case 0x47: return "identify remote slave: product code";
    case 0x48: return "identify remote slave: revision low";
    case 0x49: return "identify remote slave: revision high";
    case 0x4A: return "identify remote slave: serial low";
    case 0x4B: return "identify remote slave: serial high";
    case 0x4C: return "identify non-configured remote slave";
    case 0x4F: return "identify slave response";
    case 0x50: return "identify non-configured slave response";
    case 0x51: return "fastscan";
    case 0x5A: return "inquire vendor-ID";
    case 0x5B: return "inquire product code";
    case 0x5C: return "inquire revision number";
    case 0x5D: return "inquire serial number";
    case 0x5E: return "inquire node-ID";
    default: return "";
  }
}

void decode_lss(const sim::CanFrame& f, bool from_master, DecodedFrame& d) {
  d.service = Service::Lss;
  const std::string dir = from_master ? "LSS " : "LSS response ";
  if (f.dlc < 1) {
    d.text = dir + "(empty frame)";
    return;
  }
  const std::uint8_t cs = f.data[0];
  const auto name = lss_command_text(cs);
  std::string s = dir + (name.empty() ? "command " + hex(cs, 2) : std::string(name));
  if (cs == 0x04 && from_master) s += f.data[1] ? ": configuration" : ": waiting";
  else if (cs == 0x11 && from_master) s += " " + std::to_string(f.data[1]);
  else if ((cs == 0x11 || cs == 0x13 || cs == 0x17) && !from_master)
    s += f.data[1] == 0 ? ": success" : ": error " + std::to_string(f.data[1]);
  else if (cs == 0x13 && from_master) s += " table " + std::to_string(f.data[1]) + " index " + std::to_string(f.data[2]);
  else if (cs == 0x15) s += " delay " + std::to_string(le(f, 1, 2)) + " ms";
  else if ((cs >= 0x40 && cs <= 0x43) || (cs >= 0x46 && cs <= 0x4B)) s += " " + hex(le(f, 1, 4), 8);
  else if (cs >= 0x5A && cs <= 0x5D && !from_master) s += " = " + hex(le(f, 1, 4), 8);
  else if (cs == 0x5E && !from_master) s += " = " + std::to_string(f.data[1]);
  d.text = std::move(s);
}

void decode_pdo(const sim::CanFrame& f, const DecoderContext::PdoInfo* info, const DecoderContext& ctx, DecodedFrame& d) {
  std::string s = service_name(d.service, d.pdo) + " node " + std::to_string(d.node);
  if (f.rtr) {
    d.text = s + " remote request";
    return;
  }
  if (!info || info->entries.empty()) {
    d.text = s + " [" + bytes_hex(f, 0, f.dlc) + "]";
    return;
  }
  int bit = 0;
  bool first = true;
  for (const auto& e : info->entries) {
    if (bit + e.bits > f.dlc * 8) {
      s += first ? ": (frame too short)" : ", (frame too short)";
      break;
    }
    std::uint64_t raw = 0;
    for (int i = 0; i < e.bits; ++i) {
      const int b = bit + i;
      if (f.data[static_cast<std::size_t>(b / 8)] >> (b % 8) & 1) raw |= 1ULL << i;
    }
    bit += e.bits;
    const DecoderContext::ObjectInfo* oi = nullptr;
    const std::string obj = object_text(ctx, info->node, e.index, e.sub, &oi);
    s += first ? ": " : ", ";
    first = false;
    s += obj + " = " + value_text(raw, e.bits, oi);
  }
  d.text = std::move(s);
}

}  // namespace

const DecoderContext::ObjectInfo* DecoderContext::object(std::uint8_t, std::uint16_t, std::uint8_t) const { return nullptr; }
const DecoderContext::PdoInfo* DecoderContext::pdo(std::uint32_t) const { return nullptr; }
std::string_view DecoderContext::emcy_text(std::uint8_t, std::uint16_t) const { return {}; }

std::string spaced_hex(const std::uint8_t* data, std::size_t n) {
  static constexpr char kDigits[] = "0123456789ABCDEF";
  std::string s;
  s.reserve(n * 3);
  for (std::size_t i = 0; i < n; ++i) {
    if (i) s += ' ';
    s += kDigits[data[i] >> 4];
    s += kDigits[data[i] & 0xF];
  }
  return s;
}

std::string heartbeat_consumer_text(std::uint32_t value) {
  const auto node = (value >> 16) & 0x7F;
  const auto ms = value & 0xFFFF;
  if (node == 0 || ms == 0) return "off (node " + std::to_string(node) + ", " + std::to_string(ms) + " ms)";
  return "node " + std::to_string(node) + ", " + std::to_string(ms) + " ms";
}

std::string service_name(Service s, int pdo) {
  switch (s) {
    case Service::Nmt: return "NMT";
    case Service::Sync: return "SYNC";
    case Service::Emcy: return "EMCY";
    case Service::Time: return "TIME";
    case Service::Tpdo: return pdo > 0 ? "TPDO" + std::to_string(pdo) : "TPDO";
    case Service::Rpdo: return pdo > 0 ? "RPDO" + std::to_string(pdo) : "RPDO";
    case Service::SdoRx: return "SDO_RX";
    case Service::SdoTx: return "SDO_TX";
    case Service::Heartbeat: return "HEARTBEAT";
    case Service::Lss: return "LSS";
    case Service::Other: break;
  }
  return "OTHER";
}

namespace {
std::string_view emcy_exact(std::uint16_t code) {
  switch (code) {
    case 0x0000: return "error reset / no error";
    case 0x1000: return "generic error";
    case 0x2000: return "current";
    case 0x2100: return "current, device input side";
    case 0x2200: return "current inside the device";
    case 0x2300: return "current, device output side";
    case 0x3000: return "voltage";
    case 0x3100: return "mains voltage";
    case 0x3200: return "voltage inside the device";
    case 0x3300: return "output voltage";
    case 0x4000: return "temperature";
    case 0x4100: return "ambient temperature";
    case 0x4200: return "device temperature";
    case 0x5000: return "device hardware";
    case 0x6000: return "device software";
    case 0x6100: return "internal software";
    case 0x6200: return "user software";
    case 0x6300: return "data set";
    case 0x7000: return "additional modules";
    case 0x8000: return "monitoring";
    case 0x8100: return "communication";
    case 0x8110: return "CAN overrun (objects lost)";
    case 0x8120: return "CAN in error passive mode";
    case 0x8130: return "life guard error or heartbeat error";
    case 0x8140: return "recovered from bus off";
    case 0x8150: return "CAN-ID collision";
    case 0x8200: return "protocol error";
    case 0x8210: return "PDO not processed due to length error";
    case 0x8220: return "PDO length exceeded";
    case 0x8230: return "DAM MPDO not processed, destination object not available";
    case 0x8240: return "unexpected SYNC data length";
    case 0x8250: return "RPDO timeout";
    case 0x9000: return "external error";
    case 0xF000: return "additional functions";
    case 0xFF00: return "device specific";
    default: return {};
  }
}
}  // namespace

std::string_view emcy_code_text(std::uint16_t code) {
  // The exact code, else its class: the low byte (then the low 12 bits) refine a class.
  if ((code & 0xFF00) == 0xFF00) return "device specific";
  for (const std::uint16_t mask : {0xFFFF, 0xFF00, 0xF000}) {
    const auto text = emcy_exact(static_cast<std::uint16_t>(code & mask));
    if (!text.empty() && (code == 0 || (code & mask) != 0)) return text;
  }
  return "unknown error code";
}

std::string error_register_text(std::uint8_t reg) {
  static constexpr const char* kBits[8] = {"generic",       "current",  "voltage",  "temperature",
                                           "communication", "device profile", "reserved", "manufacturer"};
  std::string s;
  for (int i = 0; i < 8; ++i) {
    if (!(reg >> i & 1)) continue;
    if (!s.empty()) s += ", ";
    s += kBits[i];
  }
  return s.empty() ? "none" : s;
}

std::string_view nmt_state_text(std::uint8_t state) {
  switch (state) {
    case 0x00: return "BOOT-UP";
    case 0x04: return "STOPPED";
    case 0x05: return "OPERATIONAL";
    case 0x7F: return "PRE-OPERATIONAL";
    default: return "unknown state";
  }
}

std::string_view nmt_command_text(std::uint8_t command) {
  switch (command) {
    case 0x01:
    case 0x02:
    case 0x80:
    case 0x81:
    case 0x82: return to_string(static_cast<NmtCommand>(command));
    default: return "unknown command";
  }
}

DecodedFrame decode_frame(const sim::CanFrame& frame) { return decode_frame(frame, DecoderContext{}); }

DecodedFrame decode_frame(const sim::CanFrame& f, const DecoderContext& ctx) {
  DecodedFrame d;
  if (f.extended) {
    d.text = "extended frame " + hex(f.id, 8) + (f.rtr ? " remote request" : " [" + bytes_hex(f, 0, f.dlc) + "]");
    return d;
  }
  const std::uint32_t id = f.id;
  const std::uint32_t fn = id & 0x780;
  const int node = static_cast<int>(id & 0x7F);

  // A PDO the context knows by its configured COB-ID wins over the pre-defined set.
  if (const auto* p = ctx.pdo(id)) {
    d.service = p->transmit ? Service::Tpdo : Service::Rpdo;
    d.pdo = p->number;
    d.node = p->node;
    decode_pdo(f, p, ctx, d);
    return d;
  }
  if (id == 0x000) {
    d.service = Service::Nmt;
    if (f.dlc < 2) {
      d.text = "NMT (short frame)";
      return d;
    }
    d.node = f.data[1];
    d.text = "NMT " + std::string(nmt_command_text(f.data[0])) + " → " +
             (f.data[1] == 0 ? std::string("all nodes") : "node " + std::to_string(f.data[1]));
    return d;
  }
  if (id == 0x080) {
    d.service = Service::Sync;
    d.text = f.dlc >= 1 ? "SYNC counter " + std::to_string(f.data[0]) : "SYNC";
    return d;
  }
  if (id == 0x100) {
    d.service = Service::Time;
    if (f.dlc < 6) {
      d.text = "TIME (short frame)";
      return d;
    }
    const std::uint32_t ms = le(f, 0, 4) & 0x0FFFFFFF;
    const std::uint32_t days = le(f, 4, 2);
    char buf[64];
    std::snprintf(buf, sizeof buf, "TIME %02u:%02u:%02u.%03u, day %u since 1984-01-01", ms / 3600000, ms / 60000 % 60,
                  ms / 1000 % 60, ms % 1000, days);
    d.text = buf;
    return d;
  }
  if (id == 0x7E5 || id == 0x7E4) {
    decode_lss(f, id == 0x7E5, d);
    return d;
  }
  if (node == 0) {
    d.text = "COB-ID " + hex(id, 3) + " [" + bytes_hex(f, 0, f.dlc) + "]";
    return d;
  }
  d.node = node;
  switch (fn) {
    case 0x080: {
      d.service = Service::Emcy;
      if (f.dlc < 3) {
        d.text = "EMCY node " + std::to_string(node) + " (short frame)";
        return d;
      }
      const auto code = static_cast<std::uint16_t>(le(f, 0, 2));
      const std::uint8_t reg = f.data[2];
      const auto own = code == 0 ? std::string_view{} : ctx.emcy_text(static_cast<std::uint8_t>(node), code);
      d.text = "EMCY node " + std::to_string(node) + " " + hex(code, 4) + " " +
               std::string(own.empty() ? emcy_code_text(code) : own) +
               ", error register " + hex(reg, 2) + " (" + error_register_text(reg) + ")";
      if (f.dlc > 3) d.text += ", data [" + bytes_hex(f, 3, f.dlc) + "]";
      return d;
    }
    case 0x180: case 0x280: case 0x380: case 0x480:
      d.service = Service::Tpdo;
      d.pdo = static_cast<int>((fn - 0x180) >> 8) + 1;
      decode_pdo(f, nullptr, ctx, d);
      return d;
    case 0x200: case 0x300: case 0x400: case 0x500:
      d.service = Service::Rpdo;
      d.pdo = static_cast<int>((fn - 0x200) >> 8) + 1;
      decode_pdo(f, nullptr, ctx, d);
      return d;
    case 0x580:
      d.service = Service::SdoTx;
      decode_sdo(f, false, ctx, d);
      return d;
    case 0x600:
      d.service = Service::SdoRx;
      decode_sdo(f, true, ctx, d);
      return d;
    case 0x700: {
      d.service = Service::Heartbeat;
      if (f.rtr) {
        d.text = "node guarding request → node " + std::to_string(node);
        return d;
      }
      if (f.dlc < 1) {
        d.text = "error control node " + std::to_string(node) + " (empty frame)";
        return d;
      }
      const std::uint8_t b = f.data[0];
      if (b == 0x00) d.text = "boot-up node " + std::to_string(node);
      else if (b & 0x80)
        d.text = "node guarding response node " + std::to_string(node) + " toggle 1 " + std::string(nmt_state_text(b & 0x7F));
      else d.text = "heartbeat node " + std::to_string(node) + " " + std::string(nmt_state_text(b));
      return d;
    }
    default: break;
  }
  d.node = -1;
  d.text = "COB-ID " + hex(id, 3) + (f.rtr ? " remote request" : " [" + bytes_hex(f, 0, f.dlc) + "]");
  return d;
}

}  // namespace canopen
