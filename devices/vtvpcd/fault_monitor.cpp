#include "devices/vtvpcd/fault_monitor.h"

#include <algorithm>
#include <bit>

#include "devices/canopen/emergency.h"

namespace vtvpcd {

namespace {
using C = Condition;
using R = Reaction;

// Error-register contributions (digest §2.10, A24): bit 0 generic, 1 current, 2 voltage,
// 4 communication, 7 manufacturer-specific.
constexpr std::uint8_t kGenericCurrent = 0x03, kGeneric = 0x01, kManufacturer = 0x81, kVoltage = 0x05,
                       kCommunication = 0x11;

constexpr std::array<FaultDefinition, static_cast<std::size_t>(C::kCount)> kDefinitions{{
    {C::AngleCmdInput, "angle_cmd_input_break", 0, 0x3400, kGenericCurrent, R::Stop, false,
     "Angle Cmd Stopp: analog angle-command input b14/b16 broken (EMCY 0x3400)"},
    {C::PressureCmdInput, "pressure_cmd_input_break", 1, 0x3400, kGenericCurrent, R::Stop, false,
     "Pressure CMD Stopp: analog pressure-command input b18/b20 broken (EMCY 0x3400)"},
    {C::PowerCmdInput, "power_cmd_input_break", 2, 0x3400, kGenericCurrent, R::Stop, false,
     "Power CMD Stopp: analog power-command input f8/f10 broken (EMCY 0x3400)"},
    {C::PressureBSensor, "pressure_b_sensor_break", 3, 0x5235, kManufacturer, R::Stop, false,
     "act.Pressure B Stopp: pressure transducer B cable break (EMCY 0x5235)"},
    {C::PressureASensor, "pressure_a_sensor_break", 4, 0x5235, kManufacturer, R::Stop, false,
     "act.Pressure A Stopp: pressure transducer A cable break (EMCY 0x5235)"},
    {C::ResAngleCmdInput, "res_angle_cmd_input_break", 5, 0x3400, kGenericCurrent, R::Stop, false,
     "res.Angle CMD Stopp: analog resulting-angle input b2/b4 broken (EMCY 0x3400)"},
    {C::LvdtElectronics, "lvdt_fault", 6, 0x5236, kManufacturer, R::Stop, false,
     "MCP-40/4742 Stopp: swivel-angle transducer (LVDT) electronics or cable (EMCY 0x5236)"},
    {C::BusTimeout, "bus_timeout", 16, 0x8100, kCommunication, R::Stop, false,
     "Timeout Stopp: life-guarding or heartbeat-consumer timeout (detected; EMCY 0x8100)"},
    {C::TriggerInvalid, "trigger_fault", 18, 0x1000, kGeneric, R::Stop, false,
     "Trigger Stopp: several binary sets selected (detected with trigger_multibit=fault; EMCY 0x1000)"},
    {C::LoopFault, "loop_fault", 19, 0x8300, kManufacturer, R::Stop, false,
     "Loop Fault Stopp: control-deviation monitoring (EMCY 0x8300)"},
    {C::LoopFaultPosition, "loop_fault_position", 19, 0x8301, kManufacturer, R::Stop, false,
     "Loop Fault Stopp: swivel-angle following error (detected with monitor_enable; EMCY 0x8301)"},
    {C::LoopFaultPressure, "loop_fault_pressure", 19, 0x8302, kManufacturer, R::Stop, false,
     "Loop Fault Stopp: pressure following error (detected with monitor_enable; EMCY 0x8302)"},
    {C::ParameterChecksum, "parameter_checksum", 22, 0x6310, kManufacturer, R::Stop, false,
     "Checksum (22): parameter data set lost or overwritten (EMCY 0x6310)"},
    {C::ConfigurationChecksum, "configuration_checksum", 23, 0x6320, kManufacturer, R::Stop, false,
     "Checksum (23): configuration / parameter error (EMCY 0x6320)"},
    {C::SupplyVoltage, "supply_voltage", 24, 0x3422, kVoltage, R::Stop, false,
     "Voltage Ub: supply voltage out of range (EMCY 0x3422)"},
    {C::ReferenceVoltage, "reference_voltage", 25, 0x3422, kVoltage, R::Stop, false,
     "Reference Voltage: internal reference / sensor supply (EMCY 0x3422)"},
    {C::Do1Short, "do1_short", 26, 0x1000, kGenericCurrent, R::Output, false, "DO1 short circuit: DO1 forced off (EMCY 0x1000)"},
    {C::OkShort, "ok_short", 27, 0x1000, kGenericCurrent, R::Output, false, "OK output short circuit: OK forced off (EMCY 0x1000)"},
    {C::Do2Short, "do2_short", 28, 0x1000, kGenericCurrent, R::Output, false, "DO2 short circuit: DO2 forced off (EMCY 0x1000)"},
    {C::Do3Short, "do3_short", 29, 0x1000, kGenericCurrent, R::Output, false, "DO3 short circuit: DO3 forced off (EMCY 0x1000)"},
    {C::Do4Short, "do4_short", 30, 0x1000, kGenericCurrent, R::Output, false, "DO4 short circuit: DO4 forced off (EMCY 0x1000)"},
    {C::Do5Short, "do5_short", 31, 0x1000, kGenericCurrent, R::Output, false, "DO5 short circuit: DO5 forced off (EMCY 0x1000)"},
    {C::Do6Short, "do6_short", 32, 0x1000, kGenericCurrent, R::Output, false, "DO6 short circuit: DO6 forced off (EMCY 0x1000)"},
    {C::Do7Short, "do7_short", 33, 0x1000, kGenericCurrent, R::Output, false, "DO7 short circuit: DO7 forced off (EMCY 0x1000)"},
    {C::Watchdog, "watchdog_reset", -1, 0x6010, kManufacturer, R::Report, true,
     "software reset by the watchdog: the card restarts (boot-up) and reports EMCY 0x6010 until acknowledged"},
    {C::SensorGeneral, "sensor_general", -1, 0x5230, kManufacturer, R::Report, false, "EMCY 0x5230 sensors in general"},
    {C::Software, "software", -1, 0x6000, kManufacturer, R::Report, false, "EMCY 0x6000 software"},
    {C::InternalSoftware, "internal_software", -1, 0x6100, kManufacturer, R::Report, false, "EMCY 0x6100 internal software"},
    {C::UserSoftware, "user_software", -1, 0x6200, kManufacturer, R::Report, false, "EMCY 0x6200 user software"},
    {C::DataSet, "data_set", -1, 0x6300, kManufacturer, R::Report, false, "EMCY 0x6300 data set"},
}};

constexpr bool rows_in_enum_order() {
  for (std::size_t i = 0; i < kDefinitions.size(); ++i)
    if (static_cast<std::size_t>(kDefinitions[i].condition) != i) return false;
  return true;
}
static_assert(rows_in_enum_order());

using Set = std::uint32_t;
constexpr Set bit_of(C c) { return Set{1} << static_cast<unsigned>(c); }

/// The rows matching `pred`, as a mask.
template <typename Pred>
constexpr Set rows_where(Pred pred) {
  Set m = 0;
  for (const auto& d : kDefinitions)
    if (pred(d)) m |= bit_of(d.condition);
  return m;
}
constexpr Set kEvents = rows_where([](const FaultDefinition& d) { return d.event; });
/// Latching with fault_latch: the numbered faults whose printed reaction is Stop (also fault 16
/// in report mode).
constexpr Set kNumberedStops = rows_where([](const FaultDefinition& d) { return d.number >= 0 && d.reaction == R::Stop; });
constexpr Set kStops = rows_where([](const FaultDefinition& d) { return d.reaction == R::Stop; });
constexpr Set kNumbered = rows_where([](const FaultDefinition& d) { return d.number >= 0; });

/// For each row, the rows that report the same EMCY code (itself included).
constexpr std::array<Set, kDefinitions.size()> same_code_rows() {
  std::array<Set, kDefinitions.size()> m{};
  for (std::size_t i = 0; i < kDefinitions.size(); ++i)
    for (const auto& o : kDefinitions)
      if (o.emcy == kDefinitions[i].emcy) m[i] |= bit_of(o.condition);
  return m;
}
constexpr auto kSameCode = same_code_rows();
}  // namespace

std::span<const FaultDefinition> fault_definitions() { return kDefinitions; }
const FaultDefinition& definition(Condition c) { return kDefinitions[static_cast<std::size_t>(c)]; }

std::optional<Condition> find_condition(std::string_view name) {
  for (const auto& d : kDefinitions)
    if (name == d.name) return d.condition;
  return std::nullopt;
}

FaultMonitor::FaultMonitor(canopen::Emergency& emcy, const Settings& settings)
    : emcy_(emcy),
      latching_(kEvents | (settings.fault_latch ? kNumberedStops : 0)),
      stopping_(settings.timeout_reaction == TimeoutReaction::Report ? kStops & ~bit(C::BusTimeout) : kStops) {}

void FaultMonitor::signal_event(Condition c) { events_ |= bit(c); }

void FaultMonitor::activate(Condition c) {
  active_ |= bit(c);
  // Move to the end of the activation order.
  auto* end = order_.begin() + order_len_;
  auto* it = std::find(order_.begin(), end, c);
  if (it != end) {
    std::rotate(it, it + 1, end);
  } else {
    order_[order_len_++] = c;
  }
}

void FaultMonitor::update(bool enable_rising_edge) {
  const Set present = injected_ | detected_ | events_;
  if ((present | active_) == 0 && register_bits_ == 0 && !emcy_.any_active()) {
    order_len_ = 0;  // nothing present, active or reported: what the steps below would leave
    return;
  }
  events_ = 0;  // an event is present for one evaluation only
  // New ones join the activation order in table order; gone ones drop unless they latch.
  for (Set rising = present & ~active_; rising != 0; rising &= rising - 1)
    activate(static_cast<Condition>(std::countr_zero(rising)));
  const Set gone = active_ & ~present & (enable_rising_edge ? ~Set{0} : ~latching_);
  active_ &= ~gone;
  sync_emergency();
}

void FaultMonitor::sync_emergency() {
  std::uint8_t bits = 0;
  for (Set a = active_; a != 0; a &= a - 1) bits |= kDefinitions[static_cast<std::size_t>(std::countr_zero(a))].error_register;
  if (bits != register_bits_) {  // 0x1001 is rewritten only when it changes (no per-cycle work)
    register_bits_ = bits;
    emcy_.set_extra_register_bits(bits);
  }
  if (active_ == 0 && !emcy_.any_active()) {  // nothing to raise, nothing to clear
    order_len_ = 0;
    return;
  }
  // New codes first (in order of occurrence), then the ones gone, so the "no error" EMCY can only
  // follow when nothing at all is left.
  for (std::size_t n = 0; n < order_len_; ++n) {
    const auto& d = definition(order_[n]);
    // The register comes from the extra bits alone: one code may carry different bits (0x1000).
    if (active(d.condition) && !emcy_.active(d.emcy)) emcy_.raise(d.emcy, 0);
  }
  for (std::size_t i = 0; i < kDefinitions.size(); ++i) {
    const auto& d = kDefinitions[i];
    if ((kSameCode[i] & active_) == 0 && emcy_.active(d.emcy)) emcy_.clear(d.emcy);
  }
  // Drop inactive entries from the activation order.
  order_len_ = static_cast<std::size_t>(
      std::remove_if(order_.begin(), order_.begin() + order_len_, [this](Condition c) { return !active(c); }) -
      order_.begin());
}

void FaultMonitor::reset() {
  detected_ = 0;
  events_ = 0;
  active_ = 0;
  order_len_ = 0;
  register_bits_ = 0;
  emcy_.set_extra_register_bits(0);
  emcy_.clear_all();  // silent: the node is initialising
}

std::uint16_t FaultMonitor::bus_status() const {
  std::uint8_t number = 0;
  bool any_numbered = false;
  if ((active_ & kNumbered) != 0) {
    for (std::size_t n = 0; n < order_len_; ++n) {
      const auto& d = definition(order_[n]);
      if (active(d.condition) && d.number >= 0) {
        number = static_cast<std::uint8_t>(d.number);  // the latest one wins
        any_numbered = true;
      }
    }
  }
  const std::uint8_t flags = emcy_.error_register();
  if (!any_numbered && flags == 0) return 0;
  return static_cast<std::uint16_t>(flags << 8 | number);
}

}  // namespace vtvpcd
