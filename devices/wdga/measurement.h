// The WDGA's 1 ms measurement cycle (digest §4): shaft → physical count (16384 steps/turn,
// 2^39 turns) → code sequence and scaling (6000h-6002h) → position filter (2105h:01) → preset
// offset → wrap-around → 6004h/6008h; speed, acceleration and jerk over the integration time
// (2105h:02, 2106h); the frequency limit (2107h); the CAM unit and the work area.
#pragma once

#include <cstdint>

#include "devices/canopen/entry_ref.h"
#include "devices/canopen/object_dictionary.h"
#include "devices/profiles/cia406/cam_unit.h"
#include "devices/profiles/cia406/motion_estimator.h"
#include "devices/profiles/cia406/rotary_position.h"
#include "devices/profiles/cia406/work_area.h"
#include "devices/wdga/endra_shaft.h"
#include "devices/wdga/position_filter.h"
#include "devices/wdga/wdga_settings.h"

namespace wdga {

class Measurement {
 public:
  Measurement(canopen::ObjectDictionary& od, const Settings& settings);

  EndraShaft& shaft() { return shaft_; }
  /// Reads the parameters from the dictionary (6000h-6002h, 2105h, 2106h, 2107h).
  void load_parameters();
  /// Power-on / Reset Node: parameters reloaded, filter and speed window restart at the shaft's
  /// present position, the stored offset applies.
  void restart(sim::Time now, cia406::Int128 offset);
  /// One internal cycle at `now`.
  void cycle(sim::Time now);

  /// The scaled count the output shows (filtered, reduced to one turn on singleturn).
  cia406::Int128 output_count() const { return output_count_; }
  const cia406::RotaryConfig& config() const { return config_; }
  /// The range positions wrap at (6002h, 0 meaning 2^32 on the 32-bit variant; physical range
  /// with scaling off).
  std::uint64_t range() const { return config_.effective_range(); }
  cia406::Int128 offset() const { return offset_; }
  /// Preset (6003h/6009h): the present position reads `value` from now on.
  void preset(std::uint64_t value);
  /// 6000h/6001h/6002h changed: the offset goes back to 0 [R, A-24].
  void parameters_changed(sim::Time now);
  /// Speed integration time changed (resizes the window: a parameter write, not per cycle).
  void window_changed();
  bool frequency_exceeded() const { return frequency_exceeded_; }

 private:
  void publish(sim::Time now);
  void restart_tracking(sim::Time now);

  canopen::ObjectDictionary& od_;
  const Settings& settings_;
  EndraShaft shaft_;
  cia406::RotaryConfig config_;
  PositionFilter filter_;
  cia406::MotionEstimator motion_;
  cia406::CamUnit cams_;
  cia406::WorkArea work_area_;
  cia406::Int128 offset_ = 0;
  cia406::Int128 output_count_ = 0;
  bool frequency_exceeded_ = false;
  unsigned filter_constant_ = 1;
  std::uint16_t speed_numerator_ = 1, speed_denominator_ = 1, frequency_limit_ = 0xFFFF;
  // Derived from config_ whenever it is loaded (it changes nowhere else).
  double units_per_rev_ = 1.0;  ///< output steps per revolution the frequency limit divides by
  std::uint64_t range_ = 1;     ///< config_.effective_range()

  // The process values, published in every cycle (6004h, 600Ch, 6030h, 6040h, 6050h, 6509h).
  canopen::EntryRef<std::uint32_t> position_;
  canopen::EntryRef<std::uint64_t> position_high_;
  canopen::EntryRef<std::int16_t> speed_, acceleration_, jerk_;
  canopen::EntryRef<std::int32_t> offset_view_;
  canopen::EntryRef<std::uint16_t> status_;
};

}  // namespace wdga
