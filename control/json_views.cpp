#include "control/json_views.h"

#include <cstdio>

#include "devices/canopen/nmt_state.h"
#include "devices/canopen/object_dictionary.h"
#include "engine/loading/value_codec.h"

namespace control {

using nlohmann::json;

json signal_json(const std::string& name, const std::string& unit, const sim::DisplayUnit& display) {
  // A port without a display unit is shown in its SI unit.
  const bool own = !display.unit.empty();
  return {{"name", name},
          {"unit", unit},
          {"display_unit", own ? std::string(display.unit) : unit},
          {"display_scale", own ? display.scale : 1.0},
          {"display_offset", own ? display.offset : 0.0},
          {"display_span", own ? display.span : 0.0}};
}

json value_json(canopen::DataType type, const std::vector<std::uint8_t>& bytes) {
  using canopen::DataType;
  if (type == DataType::VisibleString) {
    std::string s(bytes.begin(), bytes.end());
    while (!s.empty() && s.back() == '\0') s.pop_back();
    return s;
  }
  if (canopen::is_variable_length(type) || bytes.size() != canopen::type_size(type)) return hex_string(bytes.data(), bytes.size());
  if (canopen::is_real(type)) return scenario::decode_number(type, bytes);
  if (canopen::is_signed_integer(type)) return canopen::decode_signed(bytes);
  return canopen::decode_unsigned(bytes);
}

std::string hex_string(const std::uint8_t* data, std::size_t n) {
  static constexpr char kDigits[] = "0123456789ABCDEF";
  std::string s;
  s.reserve(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    s += kDigits[data[i] >> 4];
    s += kDigits[data[i] & 0xF];
  }
  return s;
}

std::string display_text(canopen::DataType type, const std::vector<std::uint8_t>& bytes, const canopen::ValueScaling& s) {
  if (!s || bytes.size() != canopen::type_size(type)) return {};
  if (canopen::is_signed_integer(type)) return canopen::scaled_text(static_cast<double>(canopen::decode_signed(bytes)), s);
  if (canopen::is_unsigned_integer(type)) return canopen::scaled_text(static_cast<double>(canopen::decode_unsigned(bytes)), s);
  return {};
}

bool parse_hex(const std::string& text, std::vector<std::uint8_t>& out, std::size_t max_bytes) {
  out.clear();
  int high = -1;
  for (const char c : text) {
    if (c == ' ') continue;
    int v;
    if (c >= '0' && c <= '9') v = c - '0';
    else if (c >= 'a' && c <= 'f') v = c - 'a' + 10;
    else if (c >= 'A' && c <= 'F') v = c - 'A' + 10;
    else return false;
    if (high < 0) {
      high = v;
    } else {
      if (out.size() == max_bytes) return false;
      out.push_back(static_cast<std::uint8_t>(high << 4 | v));
      high = -1;
    }
  }
  return high < 0;
}

std::string nmt_name(const NodeStatus& s) {
  if (!s.powered) return "OFF";
  switch (static_cast<canopen::NmtState>(s.nmt)) {
    case canopen::NmtState::Initialising: return "INITIALISING";
    case canopen::NmtState::PreOperational: return "PRE-OPERATIONAL";
    case canopen::NmtState::Operational: return "OPERATIONAL";
    case canopen::NmtState::Stopped: return "STOPPED";
  }
  return "UNKNOWN";
}

namespace {

json device_json(const NodeStatus& s) {
  const auto& p = s.profile;
  json d = {{"profile", std::string(devices::to_string(p.profile))}};
  switch (p.profile) {
    case devices::ProfileStatus::Profile::Dsp408:
      d["state"] = std::string(p.state);
      d["control_word"] = p.control_word;
      d["status_word"] = p.status_word;
      if (p.transitions > 0) {
        d["last_transition"] = {{"from", std::string(p.transition_from)},
                                {"to", std::string(p.transition_to)},
                                {"control_word", p.transition_control_word},
                                {"t_us", s.transition_t_us}};
      } else {
        d["last_transition"] = nullptr;
      }
      if (s.channel_count > 0) {  // the MD2: every channel's state machine (channel 1 is the above)
        json channels = json::array();
        for (std::size_t c = 0; c < s.channel_count; ++c) {
          const auto& ch = s.channels[c];
          json j = {{"channel", c + 1},
                    {"state", std::string(ch.state)},
                    {"control_word", ch.control_word},
                    {"status_word", ch.status_word}};
          if (ch.transitions > 0) {
            j["last_transition"] = {{"from", std::string(ch.transition_from)},
                                    {"to", std::string(ch.transition_to)},
                                    {"control_word", ch.transition_control_word},
                                    {"t_us", ch.transition_t_us}};
          } else {
            j["last_transition"] = nullptr;
          }
          channels.push_back(std::move(j));
        }
        d["channels"] = std::move(channels);
      }
      break;
    case devices::ProfileStatus::Profile::Vtvpcd: {
      d["state"] = std::string(p.state);
      json faults = json::array();
      for (std::size_t i = 0; i < p.fault_count; ++i) faults.push_back(std::string(p.faults[i]));
      d["faults"] = std::move(faults);
      break;
    }
    case devices::ProfileStatus::Profile::Cia406:
      d["operating_status"] = p.operating_status;
      d["alarms"] = p.alarms;
      d["warnings"] = p.warnings;
      break;
    case devices::ProfileStatus::Profile::Generic: break;
  }
  return d;
}

}  // namespace

json node_json(const std::string& name, const std::string& bus, const NodeStatus& s, const EmcyMeaning& meaning) {
  json emcy = json::array();
  const std::uint32_t n = std::min<std::uint32_t>(s.emcy_count, NodeStatus::kEmcyHistory);
  for (std::uint32_t k = s.emcy_count - n; k < s.emcy_count; ++k) {
    const auto& r = s.emcy[k % NodeStatus::kEmcyHistory];
    // The product's own meaning where its manual gives one (HLT 1100 FF00h: position error), else
    // CiA 301's class; the code itself is the "code" field, not repeated here.
    const auto own = meaning(r.code);
    emcy.push_back({{"t_us", r.t_us},
                    {"code", r.code},
                    {"register", r.error_register},
                    {"data", hex_string(r.data.data(), r.data.size())},
                    {"text", std::string(own.empty() ? canopen::emcy_code_text(r.code) : own) + "; register: " +
                                 canopen::error_register_text(r.error_register)}});
  }
  return {{"name", name},
          {"node_id", s.node_id},
          {"bus", bus},
          {"nmt", nmt_name(s)},
          {"error_register", s.error_register},
          {"device", device_json(s)},
          {"emcy", std::move(emcy)}};
}

json frame_json(const CapturedFrame& c, const std::string& bus, const canopen::DecodedFrame& d) {
  const auto& f = c.frame;
  char buf[sim::kCandumpMax];
  sim::format_candump(f, buf);
  char stamp[48];
  std::snprintf(stamp, sizeof stamp, "(%lld.%06lld) ", static_cast<long long>(c.t_us / 1000000),
                static_cast<long long>(c.t_us % 1000000));
  // Who sent it, as the connection set says: the node for TPDO/SDO_TX/EMCY/heartbeat/LSS response.
  const bool from_node = d.service == canopen::Service::Tpdo || d.service == canopen::Service::SdoTx ||
                         d.service == canopen::Service::Emcy ||
                         (d.service == canopen::Service::Heartbeat && !f.rtr) || (d.service == canopen::Service::Lss && f.id == 0x7E4);
  return {{"t_us", c.t_us},
          {"bus", bus},
          {"id", f.id},
          {"ext", f.extended},
          {"rtr", f.rtr},
          {"dlc", f.dlc},
          {"data", hex_string(f.data.data(), f.rtr ? 0 : f.dlc)},
          {"bytes", canopen::spaced_hex(f.data.data(), f.rtr ? 0 : f.dlc)},
          {"dir", from_node ? "node" : "master"},
          {"service", canopen::service_name(d.service, d.pdo)},
          {"node", d.node >= 0 ? json(d.node) : json(nullptr)},
          {"text", d.text},
          {"candump", std::string(stamp) + bus + " " + buf}};
}

}  // namespace control
