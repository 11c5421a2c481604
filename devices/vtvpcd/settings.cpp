#include "devices/vtvpcd/settings.h"

#include <algorithm>
#include <iterator>
#include <string_view>
#include <utility>
#include <vector>

#include "devices/settings_reader.h"
#include "devices/vtvpcd/manufacturer_objects.h"

namespace vtvpcd {

namespace {

constexpr std::pair<const char*, OutputFunction> kOutputFunctions[] = {
    {"controller_active", OutputFunction::ControllerActive}, {"angle_window", OutputFunction::AngleWindow},
    {"pressure_branch", OutputFunction::PressureBranch},     {"power_branch", OutputFunction::PowerBranch},
    {"pressure_window", OutputFunction::PressureWindow},     {"slave", OutputFunction::SlaveMode},
    {"binary_set", OutputFunction::BinarySetInUse},          {"off", OutputFunction::Off}};

/// do_functions: seven names for DO1..DO7, comma-separated.
void read_output_functions(devices::SettingsReader& r, std::array<OutputFunction, 7>& out) {
  const auto* text = r.text("do_functions");
  if (!text) return;
  std::array<OutputFunction, 7> f{};
  std::size_t n = 0;
  for (std::size_t start = 0; start <= text->size();) {
    std::size_t end = text->find(',', start);
    if (end == std::string::npos) end = text->size();
    const std::string_view name(text->data() + start, end - start);
    const auto* found = std::find_if(std::begin(kOutputFunctions), std::end(kOutputFunctions),
                                     [&](const auto& o) { return name == o.first; });
    if (found == std::end(kOutputFunctions)) {
      return r.reject("do_functions", *text,
                      "expected 7 comma-separated functions for DO1..DO7 out of controller_active, angle_window, "
                      "pressure_branch, power_branch, pressure_window, slave, binary_set, off");
    }
    if (n < f.size()) f[n] = found->second;
    ++n;
    start = end + 1;
  }
  if (n != f.size()) return r.reject("do_functions", *text, "expected exactly 7 functions (DO1..DO7)");
  out = f;
}

/// node_id_object: none, or a free manufacturer index for the node-ID (A3).
void read_node_id_object(devices::SettingsReader& r, std::uint16_t& out) {
  const auto* text = r.text("node_id_object");
  if (!text) return;
  if (*text == "none") {
    out = 0;
    return;
  }
  std::uint64_t index = 0;
  r.get("node_id_object", index, 0x2000, 0x5FFF);
  if (index == 0) return;  // not an index in range: the reader has the error
  if (find_object_spec(static_cast<std::uint16_t>(index))) {
    return r.reject("node_id_object", *text, "expected none or a free index 0x2000..0x5FFF (not a chapter-4 object)");
  }
  out = static_cast<std::uint16_t>(index);
}

void read_area(devices::SettingsReader& r, const char* name, std::vector<AreaEntry>& out) {
  const auto* text = r.text(name);
  if (!text) return;
  std::string why;
  if (!parse_area(*text, out, why)) r.reject(name, *text, why);
}

/// The settings table: one call per setting, its type, range and default (the value already in `s`).
void read(devices::SettingsReader& r, Settings& s) {
  // communication
  r.get_int("boot_delay_ms", s.boot_delay_ms, 0, 60000);
  r.get_int("reset_boot_delay_ms", s.reset_boot_delay_ms, 0, 100);
  r.get("nmt_stop_supported", s.nmt_stop_supported);
  r.get("emcy_in_preoperational", s.emcy_in_preoperational);
  r.choose("sdo_size_mode", s.sdo_size_strict, {{"lenient", false}, {"strict", true}});
  r.choose("sdo_range_mode", s.sdo_range_strict, {{"none", false}, {"strict", true}});
  r.get("expose_mapping_objects", s.expose_mapping_objects);
  r.choose("nmt_82", s.reset_communication_keeps_parameters, {{"reset_communication", false}, {"can_controller", true}});
  read_node_id_object(r, s.node_id_object);
  r.get_uint("device_type", s.device_type, 0, 0xFFFFFFFFu);
  r.get_uint("vendor_id", s.identity[0], 0, 0xFFFFFFFFu);
  r.get_uint("product_code", s.identity[1], 0, 0xFFFFFFFFu);
  r.get_uint("revision_number", s.identity[2], 0, 0xFFFFFFFFu);
  r.get_uint("serial_number", s.identity[3], 0, 0xFFFFFFFFu);
  read_area(r, "tpdo_area", s.areas.from_card);
  read_area(r, "rpdo_area", s.areas.to_card);
  r.choose("area_straddle", s.areas.straddle, {{"reject", Straddle::Reject}, {"pad", Straddle::Pad}});
  // application
  r.choose("pump_type", s.pump_type, {{"A4VSO", PumpType::A4VSO}, {"A4VSG", PumpType::A4VSG}, {"A2V", PumpType::A2V}});
  r.choose("controlled_pressure", s.controlled_pressure,
         {{"flow_side", ControlledPressure::FlowSide}, {"A", ControlledPressure::A}, {"B", ControlledPressure::B},
          {"max", ControlledPressure::Max}});
  r.choose("cmd_source", s.cmd_source, {{"bus", CommandSource::Bus}, {"analog", CommandSource::Analog}});
  r.choose("direct_mode_ramps", s.direct_mode_ramps_set0, {{"none", false}, {"set0", true}});
  r.choose("trigger_multibit", s.trigger_multibit, {{"lowest", MultiBitTrigger::Lowest}, {"fault", MultiBitTrigger::Fault}});
  r.choose("scale_0x2F0E", s.press_cmd_scale_printed, {{"327.67", false}, {"324.7", true}});
  r.choose("pressure_bus_unit", s.pressure_bus_unit,
         {{"bar", PressureBusUnit::Bar}, {"percent", PressureBusUnit::PercentOfReference}});
  r.get("fault_latch", s.fault_latch);
  r.get("monitor_enable", s.monitor_enable);
  r.choose("timeout_reaction", s.timeout_reaction, {{"stop", TimeoutReaction::Stop}, {"report", TimeoutReaction::Report}});
  read_output_functions(r, s.do_functions);
  r.get_above("p_ref_bar", s.p_ref_bar, 0, 600);
  r.get_above("k_pos", s.k_pos, 0, 1000);
  r.get("x_off_pct", s.x_off_pct, -100, 100);
  r.get_int("control_period_ms", s.control_period_ms, 1, 100);
  // built-in plant
  auto& p = s.plant;
  r.get("builtin_plant", s.builtin_plant);
  r.get_above("vg_max_cm3", p.vg_max_cm3, 0, 10000);
  r.get("speed_rpm", p.speed_rpm, 0, 10000);
  r.get_above("t_stroke_s", p.t_stroke_s, 0, 100);
  r.get_above("tau_valve_s", p.tau_valve_s, 0, 10);
  r.get_above("oil_volume_l", p.oil_volume_l, 0, 10000);
  r.get_above("beta_bar", p.beta_bar, 0, 100000);
  r.get("k_load", p.k_load, 0, 10000);
  r.get("c_leak", p.c_leak, 0, 100);
  r.get_above("p_relief_bar", p.p_relief_bar, 0, 1000);
  r.get("k_relief", p.k_relief, 0, 10000);
  r.get("p_boost_bar", p.p_boost_bar, 0, 600);
  r.get("pA_const_bar", p.pA_const_bar, 0, 600);
  r.choose("pilot_supply", p.pilot_supply, {{"external", PilotSupply::External}, {"internal", PilotSupply::Internal}});
}

}  // namespace

bool Settings::parse(const std::map<std::string, std::string>& in, Settings& out, std::string& error) {
  devices::SettingsReader r(in);
  read(r, out);
  error = r.finish();
  if (!error.empty()) return false;
  BusManagerAreas::Mapping mapping;
  std::string why;
  if (!out.areas.to_mapping(mapping, why)) {
    error = "Bus Manager areas: " + why;
    return false;
  }
  return true;
}

}  // namespace vtvpcd
