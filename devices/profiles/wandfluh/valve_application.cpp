#include "devices/profiles/wandfluh/valve_application.h"

#include "devices/canopen/store_restore.h"

namespace wandfluh {

using canopen::NmtCommand;
using canopen::NmtState;
using dsp408::DeviceState;

ValveApplication::ValveApplication(canopen::Node& node, const CommonOptions& options)
    : node_(node), common_(options), errors_(node), address_(node) {}

void ValveApplication::set_delivery_value(std::uint16_t index, std::uint8_t sub, canopen::Bytes value) {
  for (auto& d : delivery_) {
    if (d.index == index && d.sub == sub) {
      d.value = std::move(value);
      return;
    }
  }
  delivery_.push_back(Delivery{index, sub, std::move(value)});
}

void ValveApplication::install() {
  auto& od = node_.od();
  install_guarding_lock(od);
  static constexpr std::string_view kChannelMachines[] = {"dsp408.ch1", "dsp408.ch2", "dsp408.ch3", "dsp408.ch4",
                                                          "dsp408.ch5", "dsp408.ch6", "dsp408.ch7", "dsp408.ch8"};
  for (int i = 0; i < channel_count(); ++i) {
    channel(i).dsm().set_fault_reset([this] { return errors_.reset(); });
    // One channel: the device's machine ("dsp408"); several: one machine per channel.
    const std::string_view machine = channel_count() == 1 ? std::string_view("dsp408") : kChannelMachines[i % 8];
    channel(i).dsm().set_recorder(machine, [this](const devices::Transition& t) {
      if (auto* log = node_.transition_log()) {
        devices::Transition stamped = t;
        stamped.t_us = static_cast<std::uint64_t>(node_.now().time_since_epoch().count());
        log->record(stamped);
      }
    });
  }
  errors_.set_on_error([this](std::uint16_t code) {
    for (int i = 0; i < channel_count(); ++i) channel(i).dsm().error({devices::TransitionCause::DeviceFault, code, {}});
  });
  // A restore of the application group (sub 1 "all", sub 3) waits for the next reset; a save
  // of the group cancels it, as does a power cycle.
  for (std::uint8_t sub : {std::uint8_t{1}, std::uint8_t{3}}) {
    if (od.entry(0x1011, sub)) {
      od.add_observer(0x1011, sub, [this](canopen::OdEntry&, canopen::Origin o) {
        if (o == canopen::Origin::Sdo) application_restore_pending_ = true;
      });
    }
    if (od.entry(0x1010, sub)) {
      od.add_observer(0x1010, sub, [this](canopen::OdEntry&, canopen::Origin o) {
        if (o == canopen::Origin::Sdo) application_restore_pending_ = false;
      });
    }
  }
}

void ValveApplication::on_reset_application() {
  application_restore_pending_ = false;  // power-on forgets it; Reset Node applies it (stack)
  auto& memory = node_.store().memory();
  bool seeded = false;
  for (const auto& d : delivery_) {
    if (!memory.find(d.index, d.sub)) {
      memory.put(d.index, d.sub, canopen::ParameterStore::Value{false, d.value});
      seeded = true;
    }
  }
  if (seeded) node_.store().load_area(0x2000, 0xFFFF);
  if (restore_keeps_address_) {
    // A pending restore reset 0x2000/0x2001 to their defaults: back to the stored values, as
    // without a restore.
    for (std::uint16_t index : {NodeAddress::kNodeAddress, NodeAddress::kBitRate}) {
      const auto* v = memory.find(index, 0);
      auto* e = node_.od().entry(index, 0);
      if (v && e && v->bytes.size() == e->value.size()) e->value = v->bytes;
    }
  }
  errors_.clear();
  for (int i = 0; i < channel_count(); ++i) channel(i).power_on(node_cause());
  reset_model();
}

void ValveApplication::on_power_off() {
  for (int i = 0; i < channel_count(); ++i) channel(i).dsm().power_off();
}

void ValveApplication::on_reset_communication() {
  if (reset_communication_requested_ && application_restore_pending_) {
    // "The default values are set valid after the device is reset by a communication reset"
    // (§5.4.11): the application group too, not only at Reset Node.
    canopen::Bytes kept[2];
    const std::uint16_t address_objects[2] = {NodeAddress::kNodeAddress, NodeAddress::kBitRate};
    for (int i = 0; i < 2; ++i) {
      if (auto* e = node_.od().entry(address_objects[i], 0)) kept[i] = e->value.bytes();
    }
    node_.store().load_area(0x2000, 0xFFFF);
    if (restore_keeps_address_) {  // as without a restore: the values in use (saved or not) stay
      for (int i = 0; i < 2; ++i) {
        if (auto* e = node_.od().entry(address_objects[i], 0)) e->value = kept[i];
      }
    }
    for (int i = 0; i < channel_count(); ++i) channel(i).refresh_source();
  }
  reset_communication_requested_ = false;
  address_.apply();
}

void ValveApplication::after_reset_communication() { regenerate_pdos(); }

void ValveApplication::on_nmt_command(NmtCommand command) {
  switch (command) {
    case NmtCommand::ResetCommunication: {
      // TR_8 is forced (C12-C14); its EMCY can go out only after the boot-up message.
      fault_after_boot_up_ = false;
      for (int i = 0; i < channel_count(); ++i) {
        const auto s = channel(i).state();
        if (s == DeviceState::Disabled || s == DeviceState::Hold || s == DeviceState::Active ||
            (s == DeviceState::Init && common_.nmt_fault_from_init)) {
          fault_after_boot_up_ = true;
        }
      }
      reset_communication_requested_ = true;
      break;
    }
    case NmtCommand::Stop:
      // Option: signal the forced fault while EMCY is still allowed (before Stopped).
      if (common_.emcy_before_stop && node_.nmt_state() != NmtState::Stopped && force_communication_fault()) {
        errors_.latch(kCommunicationError, kCommunicationRegister, false);
      }
      break;
    case NmtCommand::ResetNode:
      for (int i = 0; i < channel_count(); ++i) channel(i).dsm().force_init(node_cause());  // TR_567
      fault_after_boot_up_ = false;
      break;
    default: break;
  }
}

bool ValveApplication::force_communication_fault() {
  bool any = false;
  for (int i = 0; i < channel_count(); ++i) any |= channel(i).dsm().forced_fault(common_.nmt_fault_from_init, node_cause());
  return any;
}

void ValveApplication::on_nmt_state_changed(NmtState from, NmtState to) {
  if (to == NmtState::Stopped) {
    // C5/C8: the EMCY cannot be sent in Stopped; it is recorded in 0x1001/0x1003.
    if (force_communication_fault()) errors_.latch(kCommunicationError, kCommunicationRegister, false);
  } else if (from == NmtState::Initialising && to == NmtState::PreOperational && fault_after_boot_up_) {
    fault_after_boot_up_ = false;
    if (force_communication_fault()) errors_.latch(kCommunicationError, kCommunicationRegister, false);
  }
}

bool ValveApplication::on_communication_error(canopen::CommError error) {
  if (error != canopen::CommError::LifeGuarding) return false;
  // Heartbeat and life guarding exclude each other: supervision rests while 0x1017 ≠ 0.
  if (common_.heartbeat_suspends_life_guarding && node_.od().get<std::uint16_t>(0x1017) != 0) return true;
  force_communication_fault();
  errors_.latch(common_.communication_emcy, kCommunicationRegister, false);
  return true;
}

}  // namespace wandfluh
