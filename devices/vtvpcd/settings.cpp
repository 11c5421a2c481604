#include "devices/vtvpcd/settings.h"

#include <charconv>
#include <cmath>
#include <functional>
#include <set>

#include "devices/settings_reader.h"
#include "devices/vtvpcd/manufacturer_objects.h"

namespace vtvpcd {

namespace {

using Apply = std::function<bool(const std::string& value, Settings& s, std::string& error)>;

struct Knob {
  const char* name;
  const char* default_text;
  Apply apply;
};

bool parse_bool(const std::string& v, bool& out) {
  if (v == "true" || v == "1" || v == "on" || v == "yes") {
    out = true;
    return true;
  }
  if (v == "false" || v == "0" || v == "off" || v == "no") {
    out = false;
    return true;
  }
  return false;
}

bool parse_u64(const std::string& v, std::uint64_t& out) {
  const char* b = v.data();
  const char* e = v.data() + v.size();
  int base = 10;
  if (v.size() > 2 && v[0] == '0' && (v[1] == 'x' || v[1] == 'X')) {
    b += 2;
    base = 16;
  }
  const auto r = std::from_chars(b, e, out, base);
  return r.ec == std::errc{} && r.ptr == e && b != e;
}

bool parse_double(const std::string& v, double& out) {
  const auto r = std::from_chars(v.data(), v.data() + v.size(), out);
  return r.ec == std::errc{} && r.ptr == v.data() + v.size() && std::isfinite(out);
}

Apply boolean(bool Settings::*field) {
  return [field](const std::string& v, Settings& s, std::string& error) {
    if (parse_bool(v, s.*field)) return true;
    error = "expects true or false";
    return false;
  };
}

Apply integer(int Settings::*field, int lo, int hi) {
  return [field, lo, hi](const std::string& v, Settings& s, std::string& error) {
    std::uint64_t u = 0;
    if (!parse_u64(v, u) || u < static_cast<std::uint64_t>(lo) || u > static_cast<std::uint64_t>(hi)) {
      error = "expects an integer " + std::to_string(lo) + ".." + std::to_string(hi);
      return false;
    }
    s.*field = static_cast<int>(u);
    return true;
  };
}

Apply u32(std::uint32_t& (*field)(Settings&)) {
  return [field](const std::string& v, Settings& s, std::string& error) {
    std::uint64_t u = 0;
    if (!parse_u64(v, u) || u > 0xFFFFFFFFu) {
      error = "expects an UNSIGNED32 (decimal or 0x hex)";
      return false;
    }
    field(s) = static_cast<std::uint32_t>(u);
    return true;
  };
}

template <typename Field>
Apply real(Field field, double lo, double hi, bool lo_open = false) {
  return [field, lo, hi, lo_open](const std::string& v, Settings& s, std::string& error) {
    double d = 0;
    if (!parse_double(v, d) || d < lo || d > hi || (lo_open && d == lo)) {
      error = std::string("expects a number in ") + (lo_open ? "(" : "[") + std::to_string(lo) + ", " +
              std::to_string(hi) + "]";
      return false;
    }
    field(s) = d;
    return true;
  };
}

template <typename E>
Apply choice(E Settings::*field, std::vector<std::pair<const char*, E>> options) {
  return [field, options](const std::string& v, Settings& s, std::string& error) {
    std::string names;
    for (const auto& [name, value] : options) {
      if (v == name) {
        s.*field = value;
        return true;
      }
      names += (names.empty() ? "" : " | ") + std::string(name);
    }
    error = "expects " + names;
    return false;
  };
}

const std::vector<std::pair<const char*, OutputFunction>>& output_function_names() {
  static const std::vector<std::pair<const char*, OutputFunction>> k{
      {"controller_active", OutputFunction::ControllerActive}, {"angle_window", OutputFunction::AngleWindow},
      {"pressure_branch", OutputFunction::PressureBranch},     {"power_branch", OutputFunction::PowerBranch},
      {"pressure_window", OutputFunction::PressureWindow},     {"slave", OutputFunction::SlaveMode},
      {"binary_set", OutputFunction::BinarySetInUse},          {"off", OutputFunction::Off}};
  return k;
}

#define PLANT(member) [](Settings& s) -> double& { return s.plant.member; }
#define APP(member) [](Settings& s) -> double& { return s.member; }

const std::vector<Knob>& knobs() {
  static const std::vector<Knob> k{
      // communication
      {"boot_delay_ms", "300", integer(&Settings::boot_delay_ms, 0, 60000)},
      {"reset_boot_delay_ms", "20", integer(&Settings::reset_boot_delay_ms, 0, 100)},
      {"nmt_stop_supported", "true", boolean(&Settings::nmt_stop_supported)},
      {"emcy_in_preoperational", "true", boolean(&Settings::emcy_in_preoperational)},
      {"sdo_size_mode", "lenient", choice(&Settings::sdo_size_strict, {{"lenient", false}, {"strict", true}})},
      {"sdo_range_mode", "none", choice(&Settings::sdo_range_strict, {{"none", false}, {"strict", true}})},
      {"expose_mapping_objects", "true", boolean(&Settings::expose_mapping_objects)},
      {"nmt_82", "reset_communication",
       choice(&Settings::reset_communication_keeps_parameters, {{"reset_communication", false}, {"can_controller", true}})},
      {"node_id_object", "none",
       [](const std::string& v, Settings& s, std::string& error) {
         if (v == "none") {
           s.node_id_object = 0;
           return true;
         }
         std::uint64_t u = 0;
         if (!parse_u64(v, u) || u < 0x2000 || u > 0x5FFF || find_object_spec(static_cast<std::uint16_t>(u))) {
           error = "expects none or a free index 0x2000..0x5FFF (not a chapter-4 object)";
           return false;
         }
         s.node_id_object = static_cast<std::uint16_t>(u);
         return true;
       }},
      {"device_type", "0", u32([](Settings& s) -> std::uint32_t& { return s.device_type; })},
      {"vendor_id", "0", u32([](Settings& s) -> std::uint32_t& { return s.identity[0]; })},
      {"product_code", "0", u32([](Settings& s) -> std::uint32_t& { return s.identity[1]; })},
      {"revision_number", "0", u32([](Settings& s) -> std::uint32_t& { return s.identity[2]; })},
      {"serial_number", "0", u32([](Settings& s) -> std::uint32_t& { return s.identity[3]; })},
      {"tpdo_area", "0x2F0F:4,0x2F26:4,0x2F19:4",
       [](const std::string& v, Settings& s, std::string& error) { return parse_area(v, s.areas.from_card, error); }},
      {"rpdo_area", "0x2C67:4,0x2C74:4,0x2C72:4,0x2046:4",
       [](const std::string& v, Settings& s, std::string& error) { return parse_area(v, s.areas.to_card, error); }},
      {"area_straddle", "reject",
       [](const std::string& v, Settings& s, std::string& error) {
         if (v == "reject" || v == "pad") {
           s.areas.straddle = v == "pad" ? Straddle::Pad : Straddle::Reject;
           return true;
         }
         error = "expects reject | pad";
         return false;
       }},
      // application
      {"pump_type", "A4VSO",
       choice(&Settings::pump_type, {{"A4VSO", PumpType::A4VSO}, {"A4VSG", PumpType::A4VSG}, {"A2V", PumpType::A2V}})},
      {"controlled_pressure", "flow_side",
       choice(&Settings::controlled_pressure, {{"flow_side", ControlledPressure::FlowSide},
                                               {"A", ControlledPressure::A},
                                               {"B", ControlledPressure::B},
                                               {"max", ControlledPressure::Max}})},
      {"cmd_source", "bus", choice(&Settings::cmd_source, {{"bus", CommandSource::Bus}, {"analog", CommandSource::Analog}})},
      {"direct_mode_ramps", "none", choice(&Settings::direct_mode_ramps_set0, {{"none", false}, {"set0", true}})},
      {"trigger_multibit", "lowest",
       choice(&Settings::trigger_multibit, {{"lowest", MultiBitTrigger::Lowest}, {"fault", MultiBitTrigger::Fault}})},
      {"scale_0x2F0E", "327.67", choice(&Settings::press_cmd_scale_printed, {{"327.67", false}, {"324.7", true}})},
      {"pressure_bus_unit", "bar",
       choice(&Settings::pressure_bus_unit,
              {{"bar", PressureBusUnit::Bar}, {"percent", PressureBusUnit::PercentOfReference}})},
      {"fault_latch", "true", boolean(&Settings::fault_latch)},
      {"monitor_enable", "false", boolean(&Settings::monitor_enable)},
      {"timeout_reaction", "stop",
       choice(&Settings::timeout_reaction, {{"stop", TimeoutReaction::Stop}, {"report", TimeoutReaction::Report}})},
      {"do_functions", "controller_active,angle_window,pressure_branch,power_branch,pressure_window,slave,binary_set",
       [](const std::string& v, Settings& s, std::string& error) {
         std::array<OutputFunction, 7> f{};
         std::size_t start = 0, n = 0;
         while (start <= v.size()) {
           std::size_t end = v.find(',', start);
           if (end == std::string::npos) end = v.size();
           const std::string name = v.substr(start, end - start);
           bool found = false;
           for (const auto& [text, value] : output_function_names()) {
             if (name == text && n < f.size()) {
               f[n] = value;
               found = true;
             }
           }
           if (!found) {
             error = "expects 7 comma-separated functions for DO1..DO7 out of controller_active, angle_window, "
                     "pressure_branch, power_branch, pressure_window, slave, binary_set, off";
             return false;
           }
           ++n;
           start = end + 1;
         }
         if (n != f.size()) {
           error = "expects exactly 7 functions (DO1..DO7)";
           return false;
         }
         s.do_functions = f;
         return true;
       }},
      {"p_ref_bar", "350", real(APP(p_ref_bar), 0, 600, true)},
      {"k_pos", "4", real(APP(k_pos), 0, 1000, true)},
      {"x_off_pct", "-25", real(APP(x_off_pct), -100, 100)},
      {"control_period_ms", "1", integer(&Settings::control_period_ms, 1, 100)},
      // built-in plant
      {"builtin_plant", "true", boolean(&Settings::builtin_plant)},
      {"vg_max_cm3", "125", real(PLANT(vg_max_cm3), 0, 10000, true)},
      {"speed_rpm", "1500", real(PLANT(speed_rpm), 0, 10000)},
      {"t_stroke_s", "0.10", real(PLANT(t_stroke_s), 0, 100, true)},
      {"tau_valve_s", "0.005", real(PLANT(tau_valve_s), 0, 10, true)},
      {"oil_volume_l", "5", real(PLANT(oil_volume_l), 0, 10000, true)},
      {"beta_bar", "14000", real(PLANT(beta_bar), 0, 100000, true)},
      {"k_load", "10", real(PLANT(k_load), 0, 10000)},
      {"c_leak", "0.02", real(PLANT(c_leak), 0, 100)},
      {"p_relief_bar", "380", real(PLANT(p_relief_bar), 0, 1000, true)},
      {"k_relief", "50", real(PLANT(k_relief), 0, 10000)},
      {"p_boost_bar", "20", real(PLANT(p_boost_bar), 0, 600)},
      {"pA_const_bar", "0", real(PLANT(pA_const_bar), 0, 600)},
      {"pilot_supply", "external",
       [](const std::string& v, Settings& s, std::string& error) {
         if (v == "external" || v == "internal") {
           s.plant.pilot_supply = v == "internal" ? PilotSupply::Internal : PilotSupply::External;
           return true;
         }
         error = "expects external | internal";
         return false;
       }},
  };
  return k;
}

#undef PLANT
#undef APP

}  // namespace

bool Settings::parse(const std::map<std::string, std::string>& in, Settings& out, std::string& error) {
  for (const auto& [name, value] : in) {
    const Knob* knob = nullptr;
    for (const auto& k : knobs())
      if (name == k.name) knob = &k;
    if (!knob) {
      std::set<std::string> names;
      for (const auto& k : knobs()) names.insert(k.name);
      error = devices::unknown_setting(name, names);
      return false;
    }
    std::string why;
    if (!knob->apply(value, out, why)) {
      error = "setting " + name + "='" + value + "': " + why;
      return false;
    }
  }
  BusManagerAreas::Mapping mapping;
  std::string why;
  if (!out.areas.to_mapping(mapping, why)) {
    error = "Bus Manager areas: " + why;
    return false;
  }
  return true;
}

std::vector<std::pair<std::string, std::string>> Settings::defaults() {
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& k : knobs()) out.emplace_back(k.name, k.default_text);
  return out;
}

}  // namespace vtvpcd
