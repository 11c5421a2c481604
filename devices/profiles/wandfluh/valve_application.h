// What the MD2 and the DSV do alike between the CiA 301 stack and their channels: resets
// (node-ID/bit rate from 0x2000/0x2001, factory-stored delivery values, PDO regeneration), the
// faults the communication state machine forces (NMT Stop and Reset Communication: TR_8 with
// EMCY 0x8100; Reset Node: TR_567), life guarding, device errors with fault reset, and the
// application-group restore that becomes valid at the next communication reset.
#pragma once

#include <cstdint>
#include <vector>

#include "devices/canopen/application.h"
#include "devices/canopen/node.h"
#include "devices/profiles/dsp408/channel_control.h"
#include "devices/profiles/wandfluh/communication.h"
#include "devices/profiles/wandfluh/device_errors.h"
#include "devices/profiles/wandfluh/node_address.h"

namespace wandfluh {

/// EMCY code and error register of the communication fault (§4.4.1).
constexpr std::uint16_t kCommunicationError = 0x8100;
constexpr std::uint8_t kCommunicationRegister = 0x11;

class ValveApplication : public canopen::Application {
 public:
  ValveApplication(canopen::Node& node, const CommonOptions& options);

  DeviceErrors& errors() { return errors_; }
  NodeAddress& address() { return address_; }
  /// A value the device holds in non-volatile memory at delivery (factory configuration or the
  /// `--node-id` of the command line): used while the memory holds no saved value for it.
  void set_delivery_value(std::uint16_t index, std::uint8_t sub, canopen::Bytes value);

  // canopen::Application
  void on_reset_application() override;
  void on_power_off() override;
  void on_reset_communication() override;
  void after_reset_communication() override;
  void on_nmt_command(canopen::NmtCommand command) override;
  void on_nmt_state_changed(canopen::NmtState from, canopen::NmtState to) override;
  bool on_communication_error(canopen::CommError error) override;

 protected:
  virtual int channel_count() const = 0;
  virtual dsp408::ChannelControl& channel(int index) = 0;  ///< 0-based
  /// Application reset: the product model back to power-on (channels are already in INIT).
  virtual void reset_model() = 0;
  /// After every communication reset: the mode-dependent default PDO mapping.
  virtual void regenerate_pdos() = 0;

  /// Call once the channels exist: fault-reset and error hooks, guarding lock, restore tracking.
  void install();
  /// Option (DSV A-18, off by default): a restore of all / application defaults leaves the node
  /// address 0x2000 and bit rate 0x2001 alone; they behave as if no restore were pending.
  void set_restore_keeps_address(bool on) { restore_keeps_address_ = on; }
  /// Option outputs_need_operational: the solenoids carry current only in NMT Operational.
  bool outputs_allowed() const {
    return !common_.outputs_need_operational || node_.nmt_state() == canopen::NmtState::Operational;
  }

  canopen::Node& node_;
  CommonOptions common_;

 private:
  /// TR_8 forced by the communication state machine; true if a channel changed.
  bool force_communication_fault();
  /// What the node's state machine is doing now, as the cause of a channel's transition.
  dsp408::DeviceStateMachine::Cause node_cause() const {
    const auto& c = node_.cause();
    return {c.cause, c.value, c.detail};
  }

  DeviceErrors errors_;
  NodeAddress address_;
  struct Delivery {
    std::uint16_t index;
    std::uint8_t sub;
    canopen::Bytes value;
  };
  std::vector<Delivery> delivery_;
  bool reset_communication_requested_ = false;  ///< Reset Communication (not Reset Node) running
  bool fault_after_boot_up_ = false;
  bool application_restore_pending_ = false;
  bool restore_keeps_address_ = false;
};

}  // namespace wandfluh
