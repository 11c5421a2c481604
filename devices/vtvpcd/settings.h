// Configuration of one emulated VT-VPCD: every reading of the manual that the digest marks [R]
// and that changes what the bus sees, plus the "configuration image" a commissioning engineer
// writes with BODAC (PDO areas, identity) and the parameters of the built-in pump model.
// Names and defaults are the digest's §4.12 keys; docs/devices/vtvpcd.md lists each one.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "devices/vtvpcd/bus_manager_areas.h"

namespace vtvpcd {

enum class PumpType : std::uint8_t { A4VSO, A4VSG, A2V };
enum class CommandSource : std::uint8_t { Bus, Analog };
enum class MultiBitTrigger : std::uint8_t { Lowest, Fault };
enum class TimeoutReaction : std::uint8_t { Stop, Report };
enum class PressureBusUnit : std::uint8_t { Bar, PercentOfReference };
enum class PilotSupply : std::uint8_t { External, Internal };

/// Which pressure the pressure controller and the power limit use (digest §4.8, A31).
enum class ControlledPressure : std::uint8_t {
  FlowSide,  ///< A4VSO/A2V: p_B; A4VSG: p_B for Angle CMD >= 0, p_A for Angle CMD < 0
  A,         ///< always act. pressure A
  B,         ///< always act. pressure B
  Max,       ///< max(p_A, p_B)
};

/// What DO1, DO2..DO7 signal (OK is fixed). Digest §3.5 / A27.
enum class OutputFunction : std::uint8_t {
  ControllerActive,  ///< Enable = 1 and no stop fault
  AngleWindow,       ///< |res. Angle CMD - act. Angle| <= 5 %
  PressureBranch,    ///< the pressure controller wins the minimum selection
  PowerBranch,       ///< the power limiter wins the minimum selection
  PressureWindow,    ///< |Press CMD - controlled pressure| <= 5 % of p_ref
  SlaveMode,         ///< Trigger bit 16
  BinarySetInUse,    ///< a binary parameter set is selected
  Off,               ///< always 0
};

/// Parameters of the built-in swivel actuator and pressure volume (digest §4.8).
struct BuiltinPlantSettings {
  double vg_max_cm3 = 125.0;
  double speed_rpm = 1500.0;
  double t_stroke_s = 0.10;
  double tau_valve_s = 0.005;
  double oil_volume_l = 5.0;
  double beta_bar = 14000.0;
  double k_load = 10.0;      ///< L/min/sqrt(bar); 0 = dead-headed
  double c_leak = 0.02;      ///< L/min/bar
  double p_relief_bar = 380.0;
  double k_relief = 50.0;    ///< L/min/bar
  double p_boost_bar = 20.0;
  double pA_const_bar = 0.0;
  PilotSupply pilot_supply = PilotSupply::External;
};

struct Settings {
  // --- communication ---------------------------------------------------------------------------
  std::uint8_t node_id = 63;           ///< factory node-ID [M]
  int boot_delay_ms = 300;             ///< power-on -> boot-up frame [R]
  int reset_boot_delay_ms = 20;        ///< NMT 0x81/0x82 -> boot-up frame (<= 100 ms) [R]
  bool nmt_stop_supported = true;      ///< A4
  bool emcy_in_preoperational = true;  ///< CiA 301; the manual lists only NMT, guarding, SDO for Pre-op
  bool sdo_size_strict = false;        ///< sdo_size_mode = lenient | strict (A14)
  bool sdo_range_strict = false;       ///< sdo_range_mode = none | strict (A15)
  bool expose_mapping_objects = true;  ///< A16
  bool reset_communication_keeps_parameters = false;  ///< nmt_82 = reset_communication | can_controller
  std::uint16_t node_id_object = 0;    ///< A3: index of a node-ID object (0 = none)
  std::uint32_t device_type = 0;       ///< A2
  std::array<std::uint32_t, 4> identity{};  ///< vendor, product, revision, serial (A2)
  BusManagerAreas areas = BusManagerAreas::manual_example();

  // --- application -----------------------------------------------------------------------------
  PumpType pump_type = PumpType::A4VSO;
  ControlledPressure controlled_pressure = ControlledPressure::FlowSide;  ///< A31
  CommandSource cmd_source = CommandSource::Bus;
  bool direct_mode_ramps_set0 = false;  ///< direct_mode_ramps = none | set0 (A29)
  MultiBitTrigger trigger_multibit = MultiBitTrigger::Lowest;  ///< A11
  bool press_cmd_scale_printed = false; ///< scale_0x2F0E = 327.67 | 324.7 (A7)
  PressureBusUnit pressure_bus_unit = PressureBusUnit::Bar;    ///< A8
  bool fault_latch = true;              ///< A21
  bool monitor_enable = false;          ///< fault 19 monitoring
  TimeoutReaction timeout_reaction = TimeoutReaction::Stop;    ///< A21
  std::array<OutputFunction, 7> do_functions{
      OutputFunction::ControllerActive, OutputFunction::AngleWindow,    OutputFunction::PressureBranch,
      OutputFunction::PowerBranch,      OutputFunction::PressureWindow, OutputFunction::SlaveMode,
      OutputFunction::BinarySetInUse};  ///< DO1, DO2..DO7 (A27)
  double p_ref_bar = 350.0;
  double k_pos = 4.0;                   ///< position-loop gain, %/%
  double x_off_pct = -25.0;             ///< pilot spool command while de-energised
  int control_period_ms = 1;

  // --- plant -----------------------------------------------------------------------------------
  bool builtin_plant = true;  ///< standalone: the built-in actuator/volume model drives the inputs
  BuiltinPlantSettings plant;

  /// Reads DeviceOptions::settings with the products' one settings reader (devices/settings_reader.h;
  /// the table is settings.cpp's read()); returns false and sets `error` on an unknown name or a
  /// bad value.
  static bool parse(const std::map<std::string, std::string>& in, Settings& out, std::string& error);
};

}  // namespace vtvpcd
