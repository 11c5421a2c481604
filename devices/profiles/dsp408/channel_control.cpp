#include "devices/profiles/dsp408/channel_control.h"

#include "devices/canopen/entry_ref.h"

namespace dsp408 {

using canopen::CheckStage;
using canopen::OdEntry;
using canopen::Origin;
using canopen::SdoAbort;

namespace {
bool from_bus(Origin o) { return o == Origin::Sdo || o == Origin::Pdo; }
}  // namespace

ChannelObjects ChannelObjects::for_channel(int c, bool with_device_mode) {
  const auto off = static_cast<std::uint16_t>(0x800 * (c - 1));
  ChannelObjects o;
  o.control_word = static_cast<std::uint16_t>(0x6040 + off);
  o.status_word = static_cast<std::uint16_t>(0x6041 + off);
  o.device_mode = with_device_mode ? static_cast<std::uint16_t>(0x6042 + off) : 0;
  o.control_mode = static_cast<std::uint16_t>(0x6043 + off);
  o.device_local = static_cast<std::uint16_t>(0x604F + off);
  return o;
}

ChannelControl::ChannelControl(canopen::ObjectDictionary& od, const ChannelObjects& objects)
    : od_(od), objects_(objects), status_entry_(canopen::EntryRef<std::uint16_t>::optional(od, objects.status_word, 0)) {
  install();
}

canopen::WriteCheck ChannelControl::mode_lock() const {
  return [this](const OdEntry&, std::span<std::uint8_t>, Origin origin) {
    if (from_bus(origin) && !modes_changeable()) return SdoAbort::DataDeviceState;
    return SdoAbort::None;
  };
}

canopen::WriteCheck ChannelControl::local_lock() const {
  return [this](const OdEntry&, std::span<std::uint8_t>, Origin origin) {
    if (from_bus(origin) && source_ != ControlSource::Bus) return SdoAbort::DataLocalControl;
    return SdoAbort::None;
  };
}

void ChannelControl::install() {
  const auto cw = objects_.control_word;
  // A control word under local or PASO control: SDO gets 0x08000021, an RPDO is dropped.
  od_.add_check(cw, 0, local_lock(), CheckStage::State);
  od_.after_write<std::uint16_t>(cw, 0, [this](std::uint16_t value, Origin origin) {
    if (from_bus(origin)) dsm_.write_control_word(value, origin == Origin::Sdo ? "SDO" : "RPDO");
  });

  od_.add_read_hook(objects_.status_word, 0, [this](OdEntry&, Origin) {
    status_entry_.set(status_word());  // the hook's entry, bound once: a read hook runs per TPDO
    return SdoAbort::None;
  });

  if (objects_.local_locks_modes) {
    for (std::uint16_t index : {objects_.device_mode, objects_.control_mode}) {
      if (index == 0) continue;
      od_.add_check(index, 0, local_lock(), CheckStage::State);
    }
  }
  for (std::uint16_t index : {objects_.device_mode, objects_.control_mode, objects_.device_local}) {
    if (index != 0) od_.add_check(index, 0, mode_lock(), CheckStage::State);
  }
  // Device local while PASO holds control: "operating mode = local" may be sent (it takes
  // effect when PASO gives control back), bus operation is refused.
  od_.add_check(
      objects_.device_local, 0,
      [this](const OdEntry&, std::span<std::uint8_t> data, Origin origin) {
        if (from_bus(origin) && paso_ && data[0] == 0) return SdoAbort::DataLocalControl;
        return SdoAbort::None;
      },
      CheckStage::State);
  od_.after_write<std::int8_t>(objects_.device_local, 0, [this](std::int8_t, Origin) { apply_source(); });
}

void ChannelControl::apply_source() {
  const bool local_selected = od_.get<std::int8_t>(objects_.device_local) == 1;
  source_ = paso_ ? ControlSource::Paso : (local_selected ? ControlSource::Local : ControlSource::Bus);
  dsm_.set_local(source_ != ControlSource::Bus);
}

void ChannelControl::power_on(DeviceStateMachine::Cause cause) {
  dsm_.power_on(cause);
  apply_source();
  publish_status();
}

void ChannelControl::set_paso_control(bool on) {
  paso_ = on;
  apply_source();
  publish_status();
}

devices::ProfileStatus ChannelControl::profile_status() const {
  devices::ProfileStatus s;
  s.profile = devices::ProfileStatus::Profile::Dsp408;
  s.state = dsm_.off() ? std::string_view("OFF") : to_string(dsm_.state());  // unpowered: no state to claim
  s.control_word = dsm_.control_word();
  s.status_word = status_word();
  s.transitions = dsm_.transitions();
  s.transition_from = to_string(dsm_.last_transition().from);
  s.transition_to = to_string(dsm_.last_transition().to);
  s.transition_control_word = dsm_.last_transition().control_word;
  return s;
}

}  // namespace dsp408
