#include "devices/vtvpcd/vtvpcd_device.h"

#include <algorithm>
#include <cmath>

#include "devices/canopen/emergency.h"
#include "devices/canopen/error_control.h"
#include "devices/canopen/heartbeat_consumer.h"
#include "devices/canopen/pdo_service.h"
#include "devices/vtvpcd/binary_set_selector.h"
#include "devices/vtvpcd/communication.h"
#include "devices/vtvpcd/dictionary.h"
#include "devices/vtvpcd/manufacturer_objects.h"

namespace vtvpcd {

namespace {
constexpr double kPaPerBar = 1e5;

/// The read-only readouts converted from an EU value every cycle, by slot.
enum EuSlot : std::size_t {
  kActAngle,
  kActPressureA,
  kActPressureB,
  kActValve,
  kAngleCmd,
  kAngleB14B16,
  kAngleB2B4,
  kPowerCmd,
  kPowerF8F10,
  kPressCmd,
  kPressB18B20,
  kPressureStroke,
  kResAngleCmd,
  kValveCmd,
  kEuSlotCount
};
constexpr std::array<std::uint16_t, kEuSlotCount> kEuSlotIndex{
    idx::kActAngle,       idx::kActPressureA,   idx::kActPressureB,  idx::kActValve,         idx::kAngleCmd,
    idx::kAngleCmdB14B16, idx::kAngleCmdB2B4,   idx::kPowerCmd,      idx::kPowerCmdF8F10,    idx::kPressCmd,
    idx::kPressCmdB18B20, idx::kPressureStroke, idx::kResAngleCmd,   idx::kValveCmd};

/// The printed scale each EU readout is converted with. Press CMD's depends on a setting (A7).
constexpr std::array<Scale, kEuSlotCount> kEuSlotScale{
    kScalePercent, kScalePercent, kScalePercent, kScaleTable,   kScalePercent,  // act. angle .. Angle CMD
    kScalePercent, kScalePercent, kScalePercent, kScalePercent, kScalePercent,  // b14/b16, b2/b4, Power CMD, f8/f10, Press CMD
    kScalePercent, kScaleTable,   kScaleTable,   kScaleTable};                  // b18/b20, stroke, res. angle, valve

bool high(double v) { return v >= 0.5; }
}  // namespace

// ---- construction -------------------------------------------------------------------------------

std::unique_ptr<VtvpcdDevice> VtvpcdDevice::create(const devices::DeviceOptions& options, std::string& error) {
  Settings settings;
  if (!options.variant.empty()) {
    error = "vtvpcd has no variants";
    return nullptr;
  }
  if (options.node_id > 127) {
    error = "node-ID " + std::to_string(options.node_id) + " is outside 1..127";
    return nullptr;
  }
  settings.node_id = options.node_id == 0 ? kFactoryNodeId : options.node_id;
  if (!Settings::parse(options.settings, settings, error)) return nullptr;
  // options.store_path is not used: the card keeps nothing written over the bus (manual §3).
  return std::unique_ptr<VtvpcdDevice>(new VtvpcdDevice(std::move(settings)));
}

VtvpcdDevice::VtvpcdDevice(Settings settings)
    : settings_(std::move(settings)), discrete_outputs_(settings_.do_functions), controller_(settings_) {
  node_ = std::make_unique<canopen::Node>("vtvpcd", build_dictionary(settings_), make_policy(settings_),
                                          settings_.node_id);
  install_communication_rules(*node_, settings_);
  node_->set_application(this);
  node_->set_transition_log(&transition_log_);
  auto& od = node_->od();
  params_ = std::make_unique<CardParameters>(od);
  faults_ = std::make_unique<FaultMonitor>(node_->emergency(), settings_);
  static_assert(std::tuple_size_v<decltype(eu_out_)> == kEuSlotCount);
  for (std::size_t s = 0; s < kEuSlotCount; ++s) {
    eu_out_[s].entry = canopen::EntryRef<std::int32_t>(od, kEuSlotIndex[s], 0);
    eu_out_[s].scale = s == kPressCmd && settings_.press_cmd_scale_printed ? kScalePressCmdPrinted : kEuSlotScale[s];
  }
  angle_binary_out_ = canopen::EntryRef<std::int32_t>(od, idx::kAngleCmdBinary, 0);
  press_binary_out_ = canopen::EntryRef<std::int32_t>(od, idx::kPressCmdBinary, 0);
  power_binary_out_ = canopen::EntryRef<std::int32_t>(od, idx::kPowerCmdBinary, 0);
  bus_status_out_ = canopen::EntryRef<std::uint16_t>(od, idx::kBusStatus, 0);
  discrete_inputs_out_ = canopen::EntryRef<std::uint16_t>(od, idx::kDiscreteInputs, 0);
  discrete_outputs_out_ = canopen::EntryRef<std::uint16_t>(od, idx::kDiscreteOutputs, 0);
  if (settings_.builtin_plant) {
    builtin_.emplace(settings_.plant, settings_.pump_type);
    apply_plant_to_inputs();
  }
  install_device_hooks();
}

VtvpcdDevice::~VtvpcdDevice() = default;

void VtvpcdDevice::install_device_hooks() {
  auto& od = node_->od();
  // Guarding switched off, or replaced by the heartbeat (A20): no life-guarding timeout is pending.
  auto guarding_changed = [this](canopen::OdEntry&, canopen::Origin) {
    const auto& o = node_->od();
    if (o.get<std::uint16_t>(0x100C) == 0 || o.get<std::uint8_t>(0x100D) == 0 || o.get<std::uint16_t>(0x1017) != 0) {
      lifeguard_timeout_ = false;
    }
  };
  od.add_observer(0x100C, 0, guarding_changed);
  od.add_observer(0x100D, 0, guarding_changed);
  od.add_observer(0x1017, 0, guarding_changed);
  // A rewritten consumer entry starts monitoring afresh.
  od.add_observer(0x1016, 1, [this](canopen::OdEntry&, canopen::Origin) { heartbeat_timeout_ = false; });
}

// ---- ports and faults ---------------------------------------------------------------------------

sim::PortList VtvpcdDevice::ports() {
  using sim::PortDirection;
  sim::PortList p{
      {"pilot_command", PortDirection::Output, "1", &pilot_command_,
       "pilot valve (HS4/EO4) command, -1..1 = valve CMD -100..100 %; the spring offset position while de-energised", sim::display::percent},
      {"swivel_angle", PortDirection::Input, "1", &swivel_angle_, "swivel angle from the pump LVDT, -1..1 = -100..100 %", sim::display::percent},
      {"pressure_a", PortDirection::Input, "Pa", &pressure_a_, "pressure transducer A", sim::display::bar},
      {"pressure_b", PortDirection::Input, "Pa", &pressure_b_, "pressure transducer B (A4VSO: pump pressure)", sim::display::bar},
      {"pilot_spool_position", PortDirection::Input, "1", &pilot_spool_position_,
       "pilot valve spool position, -1..1 (act. valve 0x2F19)", sim::display::percent},
      {"di1", PortDirection::Input, "1", &di_[0], "discrete input DI1 (binary 1), 0/1", sim::display::on_off},
      {"di2", PortDirection::Input, "1", &di_[1], "discrete input DI2 (binary 2), 0/1", sim::display::on_off},
      {"di3", PortDirection::Input, "1", &di_[2], "discrete input DI3 (binary 4), 0/1", sim::display::on_off},
      {"di4", PortDirection::Input, "1", &di_[3], "discrete input DI4 (binary 8), 0/1", sim::display::on_off},
      {"di5", PortDirection::Input, "1", &di_[4], "discrete input DI5 (Master), 0/1", sim::display::on_off},
      {"di6", PortDirection::Input, "1", &di_[5], "discrete input DI6 (binary enable), 0/1", sim::display::on_off},
      {"enable", PortDirection::Input, "1", &enable_, "controller enable input, 0/1", sim::display::on_off},
      {"angle_cmd_b14_b16", PortDirection::Input, "1", &analog_angle_b14_b16_, "analog angle command, -1..1", sim::display::percent},
      {"angle_cmd_b2_b4", PortDirection::Input, "1", &analog_angle_b2_b4_,
       "analog resulting-angle command (slave), -1..1", sim::display::percent},
      {"pressure_cmd_b18_b20", PortDirection::Input, "Pa", &analog_pressure_b18_b20_, "analog pressure command", sim::display::bar},
      {"power_cmd_f8_f10", PortDirection::Input, "1", &analog_power_f8_f10_, "analog power command, 0..1", sim::display::percent},
  };
  if (builtin_) {
    p.push_back({"builtin_load_coefficient", PortDirection::Input, "L/min/sqrt(bar)", &builtin_->load_coefficient(),
                 "built-in plant: throttle load K_L (0 = dead-headed)", sim::display::as_si});
    p.push_back({"builtin_speed", PortDirection::Input, "1/min", &builtin_->speed_rpm(),
                 "built-in plant: shaft speed (0 = standing: spring centring)", sim::display::as_si});
  }
  return p;
}

std::vector<devices::FaultInfo> VtvpcdDevice::faults() const {
  std::vector<devices::FaultInfo> out;
  for (const auto& d : fault_definitions()) out.push_back({d.name, d.description, d.emcy});
  return out;
}

std::string VtvpcdDevice::inject_fault(std::string_view name, bool active) {
  const auto c = find_condition(name);
  if (!c) return Device::inject_fault(name, active);
  if (*c == Condition::Watchdog) {
    if (!active) return {};  // an event: nothing to remove
    // The watchdog restarts the card as a power cycle does; EMCY 0x6010 follows the boot-up.
    const sim::Time now = node_->now();
    power_off();
    node_->power_on(now);
    watchdog_pending_ = true;
    return {};
  }
  faults_->set_injected(*c, active);
  return {};
}

void VtvpcdDevice::power_off() {
  node_->power_off();
  pilot_command_ = settings_.x_off_pct / 100.0;
}

// ---- application events -------------------------------------------------------------------------

std::string_view VtvpcdDevice::run_state() const {
  if (!node_->powered()) return "OFF";
  if (initialising_) return "INITIALISING";
  if (faults_->stop_active()) return "FAULT_STOP";
  return enable_ < 0.5 ? "NOT_ENABLED" : "RUNNING";
}

void VtvpcdDevice::note_run_state(devices::TransitionCause cause, std::uint32_t value, std::string_view detail) {
  const std::string_view to = run_state(), from = recorded_state_;
  if (to == from) return;
  recorded_state_ = to;
  std::string_view name;
  if (to == "OFF") name = "power off";
  else if (to == "INITIALISING") name = cause == devices::TransitionCause::NmtCommand ? "NMT 81h" : "power on";
  else if (from == "INITIALISING") name = "boot-up";
  else if (to == "FAULT_STOP") name = "stop fault";
  else if (from == "FAULT_STOP") name = "acknowledge";
  else name = to == "RUNNING" ? "enable" : "disable";
  transition_log_.record({0, static_cast<std::uint64_t>(node_->now().time_since_epoch().count()), "vtvpcd", from, to, name,
                          cause, value, detail});
}

void VtvpcdDevice::note_cycle_state(bool enable_rising) {
  const std::string_view to = run_state();
  if (to == recorded_state_) return;
  if (to == "FAULT_STOP") {
    for (const auto& d : fault_definitions()) {  // the stop fault that stopped the card
      if (d.reaction != Reaction::Stop || !faults_->active(d.condition)) continue;
      note_run_state(devices::TransitionCause::DeviceFault, d.emcy, d.name);
      return;
    }
  }
  if (recorded_state_ == "FAULT_STOP" && !enable_rising) {
    note_run_state(devices::TransitionCause::Internal, 0, "the fault's cause is gone");
    return;
  }
  note_run_state(devices::TransitionCause::Input, enable_ < 0.5 ? 0 : 1, "enable input");
}

void VtvpcdDevice::on_power_off() { note_run_state(devices::TransitionCause::Power, 0, {}); }

void VtvpcdDevice::on_reset_application() {
  // Power-on or "reset of amplifier card": the RAM image is gone, the loop starts from scratch.
  initialising_ = true;
  note_run_state(node_->cause().cause, node_->cause().value, node_->cause().detail);
  controller_.reset();
  loop_monitor_.reset();
  faults_->reset();
  cycle_debt_ = sim::Duration{0};
  previous_enable_ = high(enable_);
  lifeguard_timeout_ = heartbeat_timeout_ = false;
  pilot_command_ = settings_.x_off_pct / 100.0;
}

void VtvpcdDevice::on_nmt_command(canopen::NmtCommand command) {
  if (command != canopen::NmtCommand::ResetNode && command != canopen::NmtCommand::ResetCommunication) return;
  nmt_reset_pending_ = true;
  if (settings_.node_id_object != 0) requested_node_id_ = node_->od().get<std::uint8_t>(settings_.node_id_object);
  kept_communication_.clear();
  if (command == canopen::NmtCommand::ResetCommunication && settings_.reset_communication_keeps_parameters) {
    // nmt_82 = can_controller: the CAN controller restarts, the communication parameters stay.
    for (auto& [index, object] : node_->od().objects()) {
      if (index < 0x1000 || index > 0x1FFF || index == 0x1001 || index == 0x1003) continue;
      for (const auto& [sub, entry] : object.entries) {
        auto* e = node_->od().entry(index, sub);
        kept_communication_.emplace_back(e, entry.value);
      }
    }
  }
}

void VtvpcdDevice::on_reset_communication() {
  // A node-ID written over the bus applies at the next NMT reset and is lost at power-off.
  std::uint8_t id = settings_.node_id;
  if (nmt_reset_pending_ && settings_.node_id_object != 0 && requested_node_id_ >= 1 && requested_node_id_ <= 127) {
    id = requested_node_id_;
  } else if (nmt_reset_pending_) {
    id = node_->node_id();
  }
  node_->set_pending_node_id(id);
  nmt_reset_pending_ = false;
}

void VtvpcdDevice::after_reset_communication() {
  lifeguard_timeout_ = heartbeat_timeout_ = false;  // guarding disarmed, consumers restart
  if (!kept_communication_.empty()) {
    for (auto& [entry, value] : kept_communication_) entry->value = value;
    kept_communication_.clear();
    node_->pdo().reload();
    node_->heartbeat_consumer().reload();
  }
  if (settings_.node_id_object != 0) node_->od().set<std::uint8_t>(settings_.node_id_object, 0, node_->pending_node_id());
}

void VtvpcdDevice::on_nmt_state_changed(canopen::NmtState from, canopen::NmtState to) {
  if (from == canopen::NmtState::Initialising && initialising_) {
    initialising_ = false;  // the boot-up message went out: the card runs
    note_run_state(node_->cause().cause, node_->cause().value, node_->cause().detail);
  }
  if (from == canopen::NmtState::Initialising && to == canopen::NmtState::PreOperational && watchdog_pending_) {
    watchdog_pending_ = false;
    faults_->signal_event(Condition::Watchdog);
    faults_->update(false);  // EMCY 0x6010 right after the boot-up frame
  }
}

bool VtvpcdDevice::on_communication_error(canopen::CommError error) {
  if (error == canopen::CommError::LifeGuarding) lifeguard_timeout_ = true;
  if (error == canopen::CommError::HeartbeatConsumer) heartbeat_timeout_ = true;
  faults_->set_detected(Condition::BusTimeout, lifeguard_timeout_ || heartbeat_timeout_);
  faults_->update(false);  // EMCY in the tick of the timeout
  return true;             // fault 16 is the card's own reaction (A21)
}

void VtvpcdDevice::on_communication_recovered(canopen::CommError error) {
  if (error == canopen::CommError::LifeGuarding) lifeguard_timeout_ = false;
  if (error == canopen::CommError::HeartbeatConsumer) heartbeat_timeout_ = false;
}

// ---- the control cycle --------------------------------------------------------------------------

std::uint16_t VtvpcdDevice::discrete_inputs() const {
  unsigned w = 0;
  for (std::size_t i = 0; i < di_.size(); ++i) w |= static_cast<unsigned>(high(di_[i])) << i;
  w |= static_cast<unsigned>(high(enable_)) * di::kEnable;
  return static_cast<std::uint16_t>(w);
}

void VtvpcdDevice::process(sim::Time, sim::Duration dt) {
  const sim::Duration period = sim::milliseconds(settings_.control_period_ms);
  cycle_debt_ += dt;
  while (cycle_debt_ >= period) {
    cycle_debt_ -= period;
    control_cycle(static_cast<double>(period.count()) * 1e-6);
  }
}

void VtvpcdDevice::apply_plant_to_inputs() {
  swivel_angle_ = builtin_->alpha_pct() / 100.0;
  pilot_spool_position_ = builtin_->spool_pct() / 100.0;
  pressure_a_ = builtin_->p_a_bar() * kPaPerBar;
  pressure_b_ = builtin_->p_b_bar() * kPaPerBar;
}

void VtvpcdDevice::control_cycle(double dt_s) {
  const CardParameters& p = *params_;
  const std::uint16_t di_word = discrete_inputs();
  const bool enable = (di_word & di::kEnable) != 0;
  const bool enable_rising = enable && !previous_enable_;
  previous_enable_ = enable;

  const SetSelection sel = select_binary_set(p.trigger(), di_word, settings_.trigger_multibit);

  faults_->set_detected(Condition::TriggerInvalid, sel.trigger_invalid);
  faults_->set_detected(Condition::BusTimeout, lifeguard_timeout_ || heartbeat_timeout_);
  if (settings_.monitor_enable) {
    faults_->set_detected(Condition::LoopFaultPosition, loop_monitor_.position_fault());
    faults_->set_detected(Condition::LoopFaultPressure, loop_monitor_.pressure_fault());
  }
  faults_->update(enable_rising);
  note_cycle_state(enable_rising);

  // Measured values; a broken transducer reads 0.
  const bool lvdt_ok = !faults_->active(Condition::LvdtElectronics);
  const double gain = std::clamp(to_eu(p.gain_lvdt_pump(), kScaleLvdtGain), 0.0, 200.0);
  const double zero_pump = std::clamp(to_eu(p.zeropoint_pump(), kScaleTable), -20.0, 20.0);
  const double alpha_meas = lvdt_ok ? gain / 100.0 * (swivel_angle_ * 100.0) + zero_pump : 0.0;
  const double p_a = faults_->active(Condition::PressureASensor) ? 0.0 : std::max(pressure_a_ / kPaPerBar, 0.0);
  const double p_b = faults_->active(Condition::PressureBSensor) ? 0.0 : std::max(pressure_b_ / kPaPerBar, 0.0);

  const AnalogInputs analog{analog_angle_b14_b16_ * 100.0, analog_angle_b2_b4_ * 100.0,
                            analog_pressure_b18_b20_ / kPaPerBar, analog_power_f8_f10_ * 100.0};
  const PumpController::Inputs in{
      .energised = enable && !faults_->stop_active(),
      .alpha_meas = alpha_meas,
      .p_a = p_a,
      .p_b = p_b,
      .cmd = command_selector_.select(sel, p, analog, settings_),
      .slave = sel.slave,
      .zero_valve_pct = std::clamp(to_eu(p.zeropoint_valve(), kScaleValveZero), -12.0, 12.0),
  };
  const ControlOutputs& c = controller_.cycle(in, dt_s);
  if (settings_.monitor_enable) loop_monitor_.update(c, alpha_meas, settings_.p_ref_bar, dt_s);

  pilot_command_ = c.spool_command / 100.0;
  publish(sel, alpha_meas, p_a, p_b, di_word);

  if (builtin_) {
    builtin_->step(c.spool_command, dt_s);
    apply_plant_to_inputs();
  }
}

void VtvpcdDevice::publish(const SetSelection& sel, double alpha_meas, double p_a, double p_b, std::uint16_t di_word) {
  const ControlOutputs& c = controller_.outputs();
  const CardParameters& p = *params_;
  eu_out_[kActAngle].put(alpha_meas);
  eu_out_[kActPressureA].put(p_a);
  eu_out_[kActPressureB].put(p_b);
  eu_out_[kActValve].put(pilot_spool_position_ * 100.0);
  eu_out_[kAngleCmd].put(c.alpha_r);
  eu_out_[kAngleB14B16].put(analog_angle_b14_b16_ * 100.0);
  eu_out_[kAngleB2B4].put(analog_angle_b2_b4_ * 100.0);
  eu_out_[kPressB18B20].put(analog_pressure_b18_b20_ / kPaPerBar);
  eu_out_[kPowerF8F10].put(analog_power_f8_f10_ * 100.0);
  // The "binary" readouts carry the raw table entry of set k unchanged (A33, A40).
  angle_binary_out_.set(p.angle_cmd_binary(sel.set));
  press_binary_out_.set(p.press_cmd_binary(sel.set));
  power_binary_out_.set(p.power_cmd_binary(sel.set));
  eu_out_[kPowerCmd].put(c.power_r);
  eu_out_[kPressCmd].put(c.p_r);
  eu_out_[kPressureStroke].put(c.alpha_p);
  eu_out_[kResAngleCmd].put(c.alpha_res);
  eu_out_[kValveCmd].put(c.valve_cmd);
  discrete_inputs_out_.set(di_word);
  bus_status_out_.set(faults_->bus_status());
  OutputState os;
  os.control = &c;
  os.alpha_meas = alpha_meas;
  os.p_ref_bar = settings_.p_ref_bar;
  os.ok = !faults_->any_active();
  os.slave = sel.slave;
  os.binary = sel.binary;
  discrete_outputs_out_.set(discrete_outputs_.word(os, faults_->shorted_outputs()));
}

devices::ProfileStatus VtvpcdDevice::profile_status() {
  devices::ProfileStatus s;
  s.profile = devices::ProfileStatus::Profile::Vtvpcd;
  s.state = run_state();
  for (const auto& d : fault_definitions()) {
    if (!faults_->active(d.condition) || s.fault_count >= s.faults.size()) continue;
    s.faults[s.fault_count++] = d.name;
  }
  return s;
}

}  // namespace vtvpcd
