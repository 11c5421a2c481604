// Device control of one DSP 408 channel on the object dictionary: control word (0x6040),
// status word (0x6041), device mode (0x6042, if the product has it), control mode (0x6043) and
// device local (0x604F), at the channel's indices. It owns the channel's device state machine
// and its control source:
//   bus   (604F = 0): the control word drives the state machine;
//   local (604F = 1): the enable input drives it, bus control words are refused;
//   PASO  (operator tool, emulated as a condition): the bus has no control.
// The device-state locks are the manuals': modes may change only in INIT or DISABLED
// (0x08000022), control words are refused under local control (0x08000021).
#pragma once

#include <cstdint>
#include <functional>

#include "devices/canopen/entry_ref.h"
#include "devices/canopen/object_dictionary.h"
#include "devices/profile_status.h"
#include "devices/profiles/dsp408/control_word.h"
#include "devices/profiles/dsp408/device_state_machine.h"

namespace dsp408 {

enum class ControlSource : std::uint8_t { Bus, Local, Paso };

struct ChannelObjects {
  std::uint16_t control_word = 0x6040;
  std::uint16_t status_word = 0x6041;
  std::uint16_t device_mode = 0x6042;   ///< 0 = the product has no device mode object
  std::uint16_t control_mode = 0x6043;
  std::uint16_t device_local = 0x604F;
  /// Under local or PASO control the control mode (and device mode) are refused with
  /// 0x08000021 too, checked before the device-state lock (DSV; the MD2 manual does not say so).
  bool local_locks_modes = false;

  /// The same objects of channel `c` (1-based): base + 0x800·(c − 1).
  static ChannelObjects for_channel(int c, bool with_device_mode);
};

class ChannelControl {
 public:
  /// Installs the hooks on `od`, which must already hold the objects (and outlive this).
  ChannelControl(canopen::ObjectDictionary& od, const ChannelObjects& objects);
  ChannelControl(const ChannelControl&) = delete;
  ChannelControl& operator=(const ChannelControl&) = delete;

  /// Application reset: INIT, control word 0, control source from 0x604F.
  void power_on(DeviceStateMachine::Cause cause = {devices::TransitionCause::Boot, 0, {}});

  DeviceStateMachine& dsm() { return dsm_; }
  const DeviceStateMachine& dsm() const { return dsm_; }
  DeviceState state() const { return dsm_.state(); }
  ControlSource source() const { return source_; }
  const ChannelObjects& objects() const { return objects_; }

  /// The product's flags for bits 5, 9, 12, 13, 14 (bit 4 comes from the control source).
  /// `live_states_only`: the product sets flags only in ACTIVE and HOLD, so the status word of
  /// any other state is built without asking it (most channels of a multi-channel product idle).
  void set_status_flags(std::function<StatusFlags()> f, bool live_states_only = false) {
    flags_ = std::move(f);
    flags_live_only_ = live_states_only;
  }
  std::uint16_t status_word() const {
    const DeviceState s = dsm_.state();
    if (flags_ && (!flags_live_only_ || s == DeviceState::Active || s == DeviceState::Hold)) return word_with(flags_());
    return idle_word(s);
  }
  /// Refreshes 0x6041 in the dictionary (for change-driven TPDOs); stores only a changed word.
  void publish_status() {
    if (status_entry_) store_status(status_word());
  }
  /// The same with the product's flags as its control cycle has just computed them (what the
  /// flags function would return now): the cycle need not have them computed a second time.
  void publish_status(const StatusFlags& flags) {
    if (!status_entry_) return;
    const DeviceState s = dsm_.state();
    const bool ask = flags_ && (!flags_live_only_ || s == DeviceState::Active || s == DeviceState::Hold);
    store_status(ask ? word_with(flags) : idle_word(s));
  }

  /// Re-reads 0x604F (after the dictionary was reloaded).
  void refresh_source() { apply_source(); }
  /// Operator condition: the PASO tool takes control (or gives it back).
  void set_paso_control(bool on);

  /// Write check for objects that may change only in INIT or DISABLED (modes): 0x08000022.
  canopen::WriteCheck mode_lock() const;
  /// Write check for objects the bus may not write under local or PASO control: 0x08000021.
  canopen::WriteCheck local_lock() const;
  /// The channel as the live control plane shows it.
  devices::ProfileStatus profile_status() const;
  bool modes_changeable() const { return state() == DeviceState::Init || state() == DeviceState::Disabled; }

 private:
  void install();
  void apply_source();
  /// The word with the product's flags (bit 4 from the control source).
  std::uint16_t word_with(StatusFlags f) const {
    f.local = source_ != ControlSource::Bus;
    return dsp408::status_word(dsm_.state(), f);
  }
  /// The word of a state in which the product is not asked: state bits and bit 4 only.
  std::uint16_t idle_word(DeviceState s) const {
    return static_cast<std::uint16_t>(state_bits(s) | (source_ != ControlSource::Bus ? status::kLocal : 0u));
  }
  void store_status(std::uint16_t w) {
    status_entry_.set(w);
  }

  canopen::ObjectDictionary& od_;
  ChannelObjects objects_;
  canopen::EntryRef<std::uint16_t> status_entry_;  // 0x6041 of the channel, published every cycle
  DeviceStateMachine dsm_;
  ControlSource source_ = ControlSource::Bus;
  bool paso_ = false;
  std::function<StatusFlags()> flags_;
  bool flags_live_only_ = false;
};

}  // namespace dsp408
