// The shaft as the EnDra multiturn sensor sees it: a continuous, unbounded angle (clockwise
// positive, looking at the shaft). EnDra counts revolutions without supply, so the position after
// a power cycle is simply the angle at power-on — no turn is ever lost, however far the shaft
// turned while the node was off.
//
// Inputs: `angle` (rad) and `speed` (rad/s, its derivative). The angle is the truth; between
// updates of the angle input the shaft advances with the speed input, so a plant that steps
// slower than the 1 ms sample cycle, or a standalone node with only `--set speed=…`, still turns
// smoothly — also while the node is powered off. A scripted signal replaces both inputs.
#pragma once

#include "devices/profiles/cia406/scripted_input.h"
#include "sim/time.h"

namespace wdga {

class EndraShaft {
 public:
  double angle = 0.0;  ///< input port, rad
  double speed = 0.0;  ///< input port, rad/s

  void set_signal(const cia406::ScriptedInput& signal) { signal_ = signal; }
  /// Shaft position at `now` in revolutions.
  double revolutions(sim::Time now);

 private:
  cia406::ScriptedInput signal_;
  double anchor_angle_ = 0.0;
  sim::Time anchor_time_{};
  bool anchored_ = false;
};

}  // namespace wdga
