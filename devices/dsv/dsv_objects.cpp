#include "devices/dsv/dsv_objects.h"

#include <array>

namespace dsv {

namespace {

using canopen::Access;
using DT = canopen::DataType;
constexpr Access RW = Access::ReadWrite, RO = Access::ReadOnly;
constexpr Shape V = Shape::Var, R = Shape::Record;
constexpr std::int64_t kNoLimit = 1, kNoLimitHi = 0;  // low > high: no static range

constexpr ModeSet M1 = modes({1}), M3 = modes({3}), M4 = modes({4}), M6 = modes({6}), M7 = modes({7}), M9 = modes({9});
constexpr ModeSet M13 = modes({1, 3}), M136 = modes({1, 3, 6}), M34 = modes({3, 4}), M479 = modes({4, 7, 9}),
                  M679 = modes({6, 7, 9});

constexpr std::int64_t kImin = kDefaultImin, kImax = kDefaultImax, kDitherFreq = kDefaultDitherFrequency,
                       kDitherAmp = kDefaultDitherAmplitude, kOpMode = kDefaultModeOfOperation;

const std::array kObjects = {
    // --- general (§5.4.28, §5.4.32, §5.4.61-65, §5.4.74) ---------------------------------------
    ObjectSpec{0x2042, "Mode of operation", V, DT::Integer8, RW, false, kOpMode, 0, 3, M136, Rule::ModeOfOperation},
    ObjectSpec{0x2043, "Error handling", V, DT::Unsigned8, RW, false, 0, 0, 3, kAllModes, Rule::ErrorHandling},
    ObjectSpec{0x2044, "System control", V, DT::Integer8, RW, false, 0, 0, 1, M479},
    ObjectSpec{0x2045, "Inversion solenoid output A", V, DT::Integer8, RW, false, 0, 0, 1, M479},
    ObjectSpec{0x2046, "Inversion solenoid output B", V, DT::Integer8, RW, false, 0, 0, 1, M479},
    ObjectSpec{0x2047, "Imin always active", V, DT::Integer8, RW, false, 0, 0, 1, M479},
    ObjectSpec{0x2048, "Solenoid In Position", V, DT::Integer8, RW, false, 0, 0, 1, M479},
    ObjectSpec{0x2050, "Internal resolution", R, DT::Unsigned32, RO, false, 1, kNoLimit, kNoLimitHi, M479},
    // --- actual value input (§5.4.41-45) --------------------------------------------------------
    ObjectSpec{0x2200, "Signal type actual value", V, DT::Integer8, RW, false, 0, 0, 3, M479, Rule::SignalType},
    ObjectSpec{0x2201, "Cablebreak actual value", V, DT::Integer8, RW, false, 0, 0, 1, M479, Rule::CableBreak},
    ObjectSpec{0x2202, "Displayed unit", V, DT::Integer8, RW, false, 0, 0, 4, M479, Rule::DisplayedUnit},
    ObjectSpec{0x6201, "Used input actual value", V, DT::Integer8, RW, false, 2, 2, 2, M479},
    ObjectSpec{0x6202, "Measuringsystem type", V, DT::Integer8, RW, false, 0, -1, 67, M479, Rule::MeasuringSystem},
    // --- scaling of the actual value (§5.4.57-60) ------------------------------------------------
    ObjectSpec{0x6220, "Min reference (pressure)", R, DT::Integer32, RW, false, 0, kNoLimit, kNoLimitHi, M4, Rule::Scaled},
    ObjectSpec{0x6221, "Max reference (pressure)", R, DT::Integer32, RW, false, 0, kNoLimit, kNoLimitHi, M4, Rule::Scaled},
    ObjectSpec{0x6224, "Min interface (pressure)", R, DT::Integer32, RW, false, 0, kNoLimit, kNoLimitHi, M4, Rule::Interface},
    ObjectSpec{0x6225, "Max interface (pressure)", R, DT::Integer32, RW, false, 0, kNoLimit, kNoLimitHi, M4, Rule::Interface},
    ObjectSpec{0x2222, "Min reference (speed)", R, DT::Integer32, RW, false, 0, kNoLimit, kNoLimitHi, M7, Rule::Scaled},
    ObjectSpec{0x2223, "Max reference (speed)", R, DT::Integer32, RW, false, 0, kNoLimit, kNoLimitHi, M7, Rule::Scaled},
    ObjectSpec{0x2220, "Min interface (speed)", R, DT::Integer32, RW, false, 0, kNoLimit, kNoLimitHi, M7, Rule::Interface},
    ObjectSpec{0x2221, "Max interface (speed)", R, DT::Integer32, RW, false, 0, kNoLimit, kNoLimitHi, M7, Rule::Interface},
    ObjectSpec{0x6230, "Min reference (position)", R, DT::Integer32, RW, false, 0, kNoLimit, kNoLimitHi, M9, Rule::Scaled},
    ObjectSpec{0x6231, "Max reference (position)", R, DT::Integer32, RW, false, 0, kNoLimit, kNoLimitHi, M9, Rule::Scaled},
    ObjectSpec{0x6233, "Min interface (position)", R, DT::Integer32, RW, false, 0, kNoLimit, kNoLimitHi, M9, Rule::Interface},
    ObjectSpec{0x6234, "Max interface (position)", R, DT::Integer32, RW, false, 0, kNoLimit, kNoLimitHi, M9, Rule::Interface},
    // --- ramps and speeds (§5.4.33-39) ----------------------------------------------------------
    ObjectSpec{0x6330, "vpoc dvg ramp type", V, DT::Integer8, RW, false, 0, 0, 3, M1, Rule::RampType, Shared::RampType},
    ObjectSpec{0x63B0, "vprc dvg ramp type", V, DT::Integer8, RW, false, 0, 0, 3, M3, Rule::RampType, Shared::RampType},
    ObjectSpec{0x64B0, "dcol dvg ramp type", V, DT::Integer8, RW, false, 0, 0, 3, M6, Rule::RampType, Shared::RampType},
    ObjectSpec{0x6332, "vpoc ramp A up", R, DT::Unsigned16, RW, false, 0, 0, 51000, M1, Rule::None, Shared::RampAUp},
    ObjectSpec{0x63B2, "vprc ramp A up", R, DT::Unsigned16, RW, false, 0, 0, 51000, M3, Rule::None, Shared::RampAUp},
    ObjectSpec{0x64B2, "dcol ramp A up", R, DT::Unsigned32, RW, false, 0, 0, 51000, M6, Rule::None, Shared::RampAUp},
    ObjectSpec{0x6333, "vpoc ramp B up", R, DT::Unsigned16, RW, false, 0, 0, 51000, M1, Rule::None, Shared::RampBUp},
    ObjectSpec{0x63B3, "vprc ramp B up", R, DT::Unsigned16, RW, false, 0, 0, 51000, M3, Rule::None, Shared::RampBUp},
    ObjectSpec{0x64B3, "dcol ramp B up", R, DT::Unsigned32, RW, false, 0, 0, 51000, M6, Rule::None, Shared::RampBUp},
    ObjectSpec{0x6335, "vpoc ramp A down", R, DT::Unsigned16, RW, false, 0, 0, 51000, M1, Rule::None, Shared::RampADown},
    ObjectSpec{0x63B5, "vprc ramp A down", R, DT::Unsigned16, RW, false, 0, 0, 51000, M3, Rule::None, Shared::RampADown},
    ObjectSpec{0x64B5, "dcol ramp A down", R, DT::Unsigned32, RW, false, 0, 0, 51000, M6, Rule::None, Shared::RampADown},
    ObjectSpec{0x6336, "vpoc ramp B down", R, DT::Unsigned16, RW, false, 0, 0, 51000, M1, Rule::None, Shared::RampBDown},
    ObjectSpec{0x63B6, "vprc ramp B down", R, DT::Unsigned16, RW, false, 0, 0, 51000, M3, Rule::None, Shared::RampBDown},
    ObjectSpec{0x64B6, "dcol ramp B down", R, DT::Unsigned32, RW, false, 0, 0, 51000, M6, Rule::None, Shared::RampBDown},
    ObjectSpec{0x22B2, "Speed positive", R, DT::Unsigned32, RW, false, 0, 0, 2000000, M479},
    ObjectSpec{0x22B3, "Speed negative", R, DT::Unsigned32, RW, false, 0, 0, 2000000, M479},
    ObjectSpec{0x62F0, "Inverting preset value", V, DT::Integer8, RW, false, 1, -1, 1, M13},
    // --- solenoid outputs (§5.4.46-56) ----------------------------------------------------------
    ObjectSpec{0x6343, "vpoc Imin A", R, DT::Integer16, RW, false, kImin, 0, 16384, M1, Rule::IminA, Shared::IminA},
    ObjectSpec{0x63C3, "vprc Imin A", R, DT::Integer16, RW, false, kImin, 0, 16384, M34, Rule::IminA, Shared::IminA},
    ObjectSpec{0x62B1, "drv Imin A", R, DT::Integer32, RW, false, kImin, 0, 16384, M679, Rule::IminA, Shared::IminA},
    ObjectSpec{0x2340, "vpoc Imax A", R, DT::Integer16, RW, false, kImax, 0, 16384, M1, Rule::ImaxA, Shared::ImaxA},
    ObjectSpec{0x23C0, "vprc Imax A", R, DT::Integer16, RW, false, kImax, 0, 16384, M34, Rule::ImaxA, Shared::ImaxA},
    ObjectSpec{0x2243, "drv Imax A", R, DT::Integer32, RW, false, kImax, 0, 16384, M679, Rule::ImaxA, Shared::ImaxA},
    ObjectSpec{0x6344, "vpoc Imin B", R, DT::Integer16, RW, false, kImin, 0, 16384, M1, Rule::IminB, Shared::IminB},
    ObjectSpec{0x63C4, "vprc Imin B", R, DT::Integer16, RW, false, kImin, 0, 16384, M34, Rule::IminB, Shared::IminB},
    ObjectSpec{0x62B2, "drv Imin B", R, DT::Integer32, RW, false, kImin, 0, 16384, M679, Rule::IminB, Shared::IminB},
    ObjectSpec{0x2341, "vpoc Imax B", R, DT::Integer16, RW, false, kImax, 0, 16384, M1, Rule::ImaxB, Shared::ImaxB},
    ObjectSpec{0x23C1, "vprc Imax B", R, DT::Integer16, RW, false, kImax, 0, 16384, M34, Rule::ImaxB, Shared::ImaxB},
    ObjectSpec{0x2244, "drv Imax B", R, DT::Integer32, RW, false, kImax, 0, 16384, M679, Rule::ImaxB, Shared::ImaxB},
    ObjectSpec{0x6342, "vpoc dead band compensation type", V, DT::Integer8, RW, false, 0, 0, 1, M1, Rule::None, Shared::DeadbandType},
    ObjectSpec{0x63C2, "vprc dead band compensation type", V, DT::Integer8, RW, false, 0, 0, 1, M3, Rule::None, Shared::DeadbandType},
    ObjectSpec{0x2242, "drv dead band compensation type", V, DT::Integer8, RW, false, 0, 0, 1, M6, Rule::None, Shared::DeadbandType},
    ObjectSpec{0x6345, "vpoc dead band threshold A", R, DT::Integer16, RW, false, 0, 0, 16384, M1, Rule::None, Shared::DeadbandA},
    ObjectSpec{0x63C5, "vprc dead band threshold A", R, DT::Integer16, RW, false, 0, 0, 16384, M3, Rule::None, Shared::DeadbandA},
    ObjectSpec{0x62B3, "drv dead band threshold A", R, DT::Integer16, RW, false, 0, 0, 16384, M6, Rule::None, Shared::DeadbandA},
    ObjectSpec{0x6B45, "vpoc dead band threshold B", R, DT::Integer16, RW, false, 0, 0, 16384, M1, Rule::None, Shared::DeadbandB},
    ObjectSpec{0x6BC5, "vprc dead band threshold B", R, DT::Integer16, RW, false, 0, 0, 16384, M3, Rule::None, Shared::DeadbandB},
    ObjectSpec{0x6360, "vpoc dither type", V, DT::Integer8, RW, false, 0, 0, 1, M1, Rule::None, Shared::DitherType},
    ObjectSpec{0x63E0, "vprc dither type", V, DT::Integer8, RW, false, 0, 0, 1, M34, Rule::None, Shared::DitherType},
    ObjectSpec{0x62D0, "drv dither type", V, DT::Integer8, RW, false, 0, 0, 1, M679, Rule::None, Shared::DitherType},
    ObjectSpec{0x6361, "vpoc dither amplitude", R, DT::Integer16, RW, false, kDitherAmp, 0, 4266, M1, Rule::None, Shared::DitherAmplitude},
    ObjectSpec{0x63E1, "vprc dither amplitude", R, DT::Integer16, RW, false, kDitherAmp, 0, 4266, M34, Rule::None, Shared::DitherAmplitude},
    ObjectSpec{0x62D1, "drv dither amplitude", R, DT::Integer16, RW, false, kDitherAmp, 0, 4266, M679, Rule::None, Shared::DitherAmplitude},
    ObjectSpec{0x6362, "vpoc dither frequency", R, DT::Integer16, RW, false, kDitherFreq, 20, 500, M1, Rule::DitherFrequency, Shared::DitherFrequency},
    ObjectSpec{0x63E2, "vprc dither frequency", R, DT::Integer16, RW, false, kDitherFreq, 20, 500, M34, Rule::DitherFrequency, Shared::DitherFrequency},
    ObjectSpec{0x62D2, "drv dither frequency", R, DT::Integer16, RW, false, kDitherFreq, 20, 500, M679, Rule::DitherFrequency, Shared::DitherFrequency},
    // --- controller windows (§5.4.66-73) ---------------------------------------------------------
    ObjectSpec{0x63F0, "vprc target window type", V, DT::Integer8, RW, false, 0, 0, 2, M4, Rule::WindowType},
    ObjectSpec{0x63F3, "vprc target window threshold", R, DT::Integer32, RW, false, 0, kNoLimit, kNoLimitHi, M4, Rule::Scaled},
    ObjectSpec{0x23F1, "vprc target window delay time", R, DT::Integer32, RW, false, 0, 0, 100, M4},
    ObjectSpec{0x63D1, "vprc trailing window type", V, DT::Integer8, RW, false, 0, 0, 2, M4, Rule::WindowType},
    ObjectSpec{0x63D3, "vprc trailing window threshold", R, DT::Integer32, RW, false, 0, kNoLimit, kNoLimitHi, M4, Rule::Scaled},
    ObjectSpec{0x63D2, "vprc trailing window delay time", R, DT::Integer32, RW, false, 0, 0, 100, M4},
    ObjectSpec{0x23F3, "vprc solenoid off threshold", R, DT::Integer32, RW, false, 0, kNoLimit, kNoLimitHi, M4, Rule::Scaled},
    ObjectSpec{0x23F2, "vprc solenoid off delay time", R, DT::Integer32, RW, false, 0, 0, 100, M4},
    ObjectSpec{0x6570, "dsc target window type", V, DT::Integer8, RW, false, 0, 0, 2, M7, Rule::WindowType},
    ObjectSpec{0x6573, "dsc target window threshold", R, DT::Integer32, RW, false, 0, kNoLimit, kNoLimitHi, M7, Rule::Scaled},
    ObjectSpec{0x2571, "dsc target window delay time", R, DT::Integer32, RW, false, 0, 0, 100, M7},
    ObjectSpec{0x6551, "dsc trailing window type", V, DT::Integer8, RW, false, 0, 0, 2, M7, Rule::WindowType},
    ObjectSpec{0x6553, "dsc trailing window threshold", R, DT::Integer32, RW, false, 0, kNoLimit, kNoLimitHi, M7, Rule::Scaled},
    ObjectSpec{0x6552, "dsc trailing window delay time", R, DT::Integer32, RW, false, 0, 0, 100, M7},
    ObjectSpec{0x2573, "dsc solenoid off threshold", R, DT::Integer32, RW, false, 0, kNoLimit, kNoLimitHi, M7, Rule::Scaled},
    ObjectSpec{0x2572, "dsc solenoid off delay time", R, DT::Integer32, RW, false, 0, 0, 100, M7},
    ObjectSpec{0x6670, "dpc target window type", V, DT::Integer8, RW, false, 0, 0, 2, M9, Rule::WindowType},
    ObjectSpec{0x6673, "dpc target window threshold", R, DT::Integer32, RW, false, 0, kNoLimit, kNoLimitHi, M9, Rule::Scaled},
    ObjectSpec{0x2671, "dpc target window delay time", R, DT::Integer32, RW, false, 0, 0, 100, M9},
    ObjectSpec{0x6651, "dpc trailing window type", V, DT::Integer8, RW, false, 0, 0, 2, M9, Rule::WindowType},
    ObjectSpec{0x6653, "dpc trailing window threshold", R, DT::Integer32, RW, false, 0, kNoLimit, kNoLimitHi, M9, Rule::Scaled},
    ObjectSpec{0x6652, "dpc trailing window delay time", R, DT::Integer32, RW, false, 0, 0, 100, M9},
    ObjectSpec{0x2673, "dpc solenoid off threshold", R, DT::Integer32, RW, false, 0, kNoLimit, kNoLimitHi, M9, Rule::Scaled},
    ObjectSpec{0x2672, "dpc solenoid off delay time", R, DT::Integer32, RW, false, 0, 0, 100, M9},
    // --- controller parameters (§5.4.75-90), mode 4 / 7 / 9 ----------------------------------------
    ObjectSpec{0x2300, "vprc I part not changed", V, DT::Integer8, RW, false, 0, 0, 1, M4},
    ObjectSpec{0x2301, "vprc preset offering", R, DT::Unsigned32, RW, false, 0, 0, 10000, M4},
    ObjectSpec{0x2302, "vprc speed offering", R, DT::Unsigned32, RW, false, 0, 0, 10000, M4},
    ObjectSpec{0x2303, "vprc Kp", R, DT::Unsigned32, RW, false, 0, 0, 25000, M4},
    ObjectSpec{0x2304, "vprc Kp negative", R, DT::Unsigned32, RW, false, 0, 0, 25000, M4},
    ObjectSpec{0x2305, "vprc switched integrator Ti", R, DT::Unsigned32, RW, false, 0, 0, 10000, M4},
    ObjectSpec{0x2306, "vprc switched integrator Ti negative", R, DT::Unsigned32, RW, false, 0, 0, 10000, M4},
    ObjectSpec{0x2307, "vprc switched integrator dX", R, DT::Unsigned32, RW, false, 0, kNoLimit, kNoLimitHi, M4, Rule::Scaled},
    ObjectSpec{0x2308, "vprc switched integrator dX negative", R, DT::Unsigned32, RW, false, 0, kNoLimit, kNoLimitHi, M4, Rule::Scaled},
    ObjectSpec{0x2309, "vprc D time", R, DT::Unsigned32, RW, false, 0, 0, 10000, M4},
    ObjectSpec{0x230A, "vprc D time negative", R, DT::Unsigned32, RW, false, 0, 0, 10000, M4},
    ObjectSpec{0x230B, "vprc D val", R, DT::Unsigned32, RW, false, 0, 0, 10000, M4},
    ObjectSpec{0x230C, "vprc D val negative", R, DT::Unsigned32, RW, false, 0, 0, 10000, M4},
    ObjectSpec{0x230D, "vprc I window inside", R, DT::Unsigned32, RW, false, 0, 0, 16384, M4},
    ObjectSpec{0x230E, "vprc I window inside negative", R, DT::Unsigned32, RW, false, 0, kNoLimit, kNoLimitHi, M4, Rule::Scaled},
    ObjectSpec{0x2500, "dsc I part not changed", V, DT::Integer8, RW, false, 0, 0, 1, M7},
    ObjectSpec{0x2501, "dsc preset offering", R, DT::Unsigned32, RW, false, 0, 0, 10000, M7},
    ObjectSpec{0x2502, "dsc speed offering", R, DT::Unsigned32, RW, false, 0, 0, 10000, M7},
    ObjectSpec{0x6503, "dsc Kp", R, DT::Unsigned32, RW, false, 0, 0, 25000, M7},
    ObjectSpec{0x2504, "dsc Kp negative", R, DT::Unsigned32, RW, false, 0, 0, 25000, M7},
    ObjectSpec{0x6509, "dsc switched integrator Ti", R, DT::Unsigned32, RW, false, 0, 0, 10000, M7},
    ObjectSpec{0x2506, "dsc switched integrator Ti negative", R, DT::Unsigned32, RW, false, 0, 0, 10000, M7},
    ObjectSpec{0x650A, "dsc switched integrator dX", R, DT::Unsigned32, RW, false, 0, kNoLimit, kNoLimitHi, M7, Rule::Scaled},
    ObjectSpec{0x2508, "dsc switched integrator dX negative", R, DT::Unsigned32, RW, false, 0, kNoLimit, kNoLimitHi, M7, Rule::Scaled},
    ObjectSpec{0x2509, "dsc D time", R, DT::Unsigned32, RW, false, 0, 0, 10000, M7},
    ObjectSpec{0x250A, "dsc D time negative", R, DT::Unsigned32, RW, false, 0, 0, 10000, M7},
    ObjectSpec{0x250B, "dsc D val", R, DT::Unsigned32, RW, false, 0, 0, 10000, M7},
    ObjectSpec{0x250C, "dsc D val negative", R, DT::Unsigned32, RW, false, 0, 0, 10000, M7},
    ObjectSpec{0x250D, "dsc I window inside", R, DT::Unsigned32, RW, false, 0, kNoLimit, kNoLimitHi, M7, Rule::Scaled},
    ObjectSpec{0x250E, "dsc I window inside negative", R, DT::Unsigned32, RW, false, 0, kNoLimit, kNoLimitHi, M7, Rule::Scaled},
    ObjectSpec{0x2600, "dpc I part not changed", V, DT::Integer8, RW, false, 0, 0, 1, M9},
    ObjectSpec{0x2601, "dpc preset offering", R, DT::Unsigned32, RW, false, 0, 0, 10000, M9},
    ObjectSpec{0x2602, "dpc speed offering", R, DT::Unsigned32, RW, false, 0, 0, 10000, M9},
    ObjectSpec{0x6603, "dpc Kp", R, DT::Unsigned32, RW, false, 0, 0, 25000, M9},
    ObjectSpec{0x2604, "dpc Kp negative", R, DT::Unsigned32, RW, false, 0, 0, 25000, M9},
    ObjectSpec{0x6608, "dpc switched integrator type", V, DT::Integer8, RW, false, 0, 0, 1, M9},
    ObjectSpec{0x6609, "dpc switched integrator Ti", R, DT::Unsigned32, RW, false, 0, 0, 10000, M9},
    ObjectSpec{0x2606, "dpc switched integrator Ti negative", R, DT::Unsigned32, RW, false, 0, 0, 10000, M9},
    ObjectSpec{0x660A, "dpc switched integrator dX", R, DT::Unsigned32, RW, false, 0, kNoLimit, kNoLimitHi, M9, Rule::Scaled},
    ObjectSpec{0x2608, "dpc switched integrator dX negative", R, DT::Unsigned32, RW, false, 0, kNoLimit, kNoLimitHi, M9, Rule::Scaled},
    ObjectSpec{0x2609, "dpc D time", R, DT::Unsigned32, RW, false, 0, 0, 10000, M9},
    ObjectSpec{0x260A, "dpc D time negative", R, DT::Unsigned32, RW, false, 0, 0, 10000, M9},
    ObjectSpec{0x260B, "dpc D val", R, DT::Unsigned32, RW, false, 0, 0, 10000, M9},
    ObjectSpec{0x260C, "dpc D val negative", R, DT::Unsigned32, RW, false, 0, 0, 10000, M9},
    ObjectSpec{0x260D, "dpc I window inside", R, DT::Unsigned32, RW, false, 0, kNoLimit, kNoLimitHi, M9, Rule::Scaled},
    ObjectSpec{0x260E, "dpc I window inside negative", R, DT::Unsigned32, RW, false, 0, kNoLimit, kNoLimitHi, M9, Rule::Scaled},
    // --- signals (§5.4.91-94) ---------------------------------------------------------------------
    ObjectSpec{0x6300, "vpoc setpoint", R, DT::Integer16, RW, true, 0, -16384, 16384, M1},
    ObjectSpec{0x6B00, "vpoc setpoint B", R, DT::Integer16, RW, true, 0, -16384, 16384, M1},
    ObjectSpec{0x6380, "vprc setpoint", R, DT::Integer16, RW, true, 0, -16384, 16384, M34, Rule::PressureSetpoint},
    ObjectSpec{0x6B80, "vprc setpoint B", R, DT::Integer16, RW, true, 0, -16384, 16384, M3},
    ObjectSpec{0x6480, "dcol setpoint", R, DT::Integer32, RW, true, 0, -100000, 100000, M6},
    ObjectSpec{0x6500, "dsc setpoint", R, DT::Integer32, RW, true, 0, kNoLimit, kNoLimitHi, M7, Rule::SetpointToMaxRef},
    ObjectSpec{0x6600, "dpc setpoint", R, DT::Integer32, RW, true, 0, kNoLimit, kNoLimitHi, M9, Rule::SetpointToMaxRef},
    ObjectSpec{0x6381, "vprc actual value", R, DT::Integer16, RW, true, 0, kNoLimit, kNoLimitHi, M4},
    ObjectSpec{0x6501, "dsc actual value", R, DT::Integer32, RW, true, 0, kNoLimit, kNoLimitHi, M7},
    ObjectSpec{0x6601, "dpc actual value", R, DT::Integer32, RW, true, 0, kNoLimit, kNoLimitHi, M9},
    ObjectSpec{0x63D0, "vprc control deviation", R, DT::Integer16, RW, false, 0, kNoLimit, kNoLimitHi, M4},
    ObjectSpec{0x6550, "dsc control deviation", R, DT::Integer32, RW, false, 0, kNoLimit, kNoLimitHi, M7},
    ObjectSpec{0x6650, "dpc control deviation", R, DT::Integer32, RW, false, 0, kNoLimit, kNoLimitHi, M9},
};

}  // namespace

std::span<const ObjectSpec> application_objects() { return kObjects; }

const ObjectSpec* find_spec(std::uint16_t index) {
  for (const auto& s : kObjects)
    if (s.index == index) return &s;
  return nullptr;
}

ModeSet modes_of(std::uint16_t index) {
  switch (index) {
    case 0x2000: case 0x2001: case 0x2002:
    case 0x6040: case 0x6041: case 0x6043: case 0x604F:
    case 0x6050: case 0x6052: case 0x6054: case 0x6057: case 0x605F: return kAllModes;
    case 0x2344: return M1;
    case 0x23C4: return M3;
    default: break;
  }
  const auto* s = find_spec(index);
  return s ? s->modes : 0;
}

}  // namespace dsv
