#include "devices/vtvpcd/card_parameters.h"

#include "devices/vtvpcd/manufacturer_objects.h"

namespace vtvpcd {

namespace {
template <typename T, std::size_t N>
void bind_table(std::array<canopen::EntryRef<T>, N>& table, canopen::ObjectDictionary& od, std::uint16_t base,
                int stride) {
  for (std::size_t i = 0; i < N; ++i)
    table[i] = canopen::EntryRef<T>(od, static_cast<std::uint16_t>(base + stride * static_cast<int>(i)), 0);
}
}  // namespace

CardParameters::CardParameters(canopen::ObjectDictionary& od)
    : trigger_(od, idx::kTrigger, 0),
      zeropoint_pump_(od, idx::kZeropointPump, 0),
      zeropoint_valve_(od, idx::kZeropointValve, 0),
      gain_lvdt_pump_(od, idx::kGainLvdtPump, 0),
      angle_cmd_bus_(od, idx::kAngleCmdBus, 0),
      pressure_cmd_bus_(od, idx::kPressureCmdBus, 0),
      power_cmd_bus_(od, idx::kPowerCmdBus, 0),
      res_angle_cmd_bus_(od, idx::kResAngleCmdBus, 0) {
  bind_table(angle_cmd_binary_, od, idx::kAngleCmdBinary0, 1);
  bind_table(press_cmd_binary_, od, idx::kPressCmdBinary0, 1);
  bind_table(power_cmd_binary_, od, idx::kPowerCmdBinary0, 1);
  bind_table(angle_ramp_binary_, od, idx::kAngleRampBinary0, 1);
  bind_table(press_ramp_binary_, od, idx::kPressRampBinary0, 1);
  bind_table(contr_p_, od, idx::kContrPBinary0, 4);
  bind_table(contr_i_, od, idx::kContrIBinary0, 4);
}

}  // namespace vtvpcd
