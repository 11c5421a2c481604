#include "devices/dsv/dsv_scaling.h"

namespace dsv {

canopen::ValueScaling value_scaling(const DsvOptions& options, std::uint16_t index, std::uint8_t sub) {
  if (sub != 1) return {};
  switch (index) {
    case 0x6300:  // preset value, m1: -16384..+16384 = -100..+100 %
    case 0x6380:  // m3 / m4: internal bus resolution, 16384 = 100 %
    case 0x6381:  // actual value, m4
    case 0x6B00:  // solenoid B set-point, op-mode 3
    case 0x6B80: return canopen::scaled("%", 100.0 / 16384);
    case 0x6480: return canopen::scaled("%", 100.0 / 100000);  // m6: -100000..+100000 = ±100 %
    case 0x6343:  // Imin A / B: 16384 = the output stage's full scale (1536 mA at 24 V, 2560 mA at 12 V)
    case 0x6344:
    case 0x62B1:
    case 0x62B2: return canopen::scaled("mA", options.current_full_scale() * 1000.0 / 16384);
    case 0x6345:  // dead band threshold: 16384 = 50 %
    case 0x62B3: return canopen::scaled("%", 50.0 / 16384);
    case 0x6361:  // dither amplitude: 4266 = 400 mA
    case 0x62D1: return canopen::scaled("mA", 400.0 / 4266);
    case 0x6362:
    case 0x62D2: return canopen::scaled("Hz", 1.0);
    case 0x6332:  // ramps: 1 ms
    case 0x6333:
    case 0x6335:
    case 0x6336:
    case 0x63B2:
    case 0x63B3: return canopen::scaled("ms", 1.0);
    default: return {};
  }
}

}  // namespace dsv
