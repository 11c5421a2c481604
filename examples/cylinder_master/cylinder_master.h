// A minimal CANopen master for vplant's reference plant, written only against the public API
// (<vplant/...>), as a team's own master code would be attached to the plant:
//   1. after the nodes' boot-up, NMT Start all nodes and produce SYNC every 10 ms;
//   2. SDO-download the VT-VPCD pump controller's "Angle CMD (BUS)" (0x2C72, INTEGER32,
//      16384 = 50 % swivel angle) and wait for the download response;
//   3. after the pump has settled, send the DSV's RPDO1 [control word 6040h = 0x0007, set point
//      = +50 %]: the DSV enters DEVICE_MODE_ACTIVE (status word 0x000F in its TPDO1) and opens
//      P→A, the cylinder extends;
//   4. watch the HLT 1100's TPDO2 (sent on every SYNC: 6020h:01, INTEGER32 in 0.1 mm steps) until
//      the position reaches the target.
// Node-IDs, COB-IDs and mappings are those of scenarios/reference-plant.yaml
// (docs/devices/dsv.md, hlt1100.md, vtvpcd.md).
#pragma once

#include <vplant/simulation.h>

#include <chrono>
#include <cstdint>
#include <string>

namespace example {

class CylinderMaster {
 public:
  struct Config {
    std::uint8_t pump_node = 63;
    std::uint8_t valve_node = 2;
    std::uint8_t sensor_node = 5;
    std::int32_t pump_angle = 16384;     ///< 0x2C72: 32768 = 100 % swivel angle
    std::int16_t valve_set_point = 8192; ///< 6300h: 16384 = 100 % (bipolar: + = P→A, extend)
    std::int32_t target_steps = 2000;    ///< 200 mm in the HLT 1100's 0.1 mm steps
    vplant::Duration boot_wait = std::chrono::milliseconds(400);
    vplant::Duration pump_settle = std::chrono::milliseconds(1000);
    vplant::Duration sync_period = std::chrono::milliseconds(10);
  };
  enum class Phase { Booting, CommandingPump, PumpSettling, EnablingValve, Extending, Reached, Failed };

  explicit CylinderMaster(vplant::Simulation& sim) : CylinderMaster(sim, Config{}) {}
  CylinderMaster(vplant::Simulation& sim, Config config);

  Phase phase() const { return phase_; }
  bool reached() const { return phase_ == Phase::Reached; }
  bool failed() const { return phase_ == Phase::Failed; }
  const std::string& failure() const { return failure_; }
  /// When the DSV's status word first showed DEVICE_MODE_ACTIVE.
  vplant::Time valve_active_at() const { return active_at_; }
  /// When the HLT 1100's TPDO2 first showed the target position.
  vplant::Time reached_at() const { return reached_at_; }
  /// The last position the HLT 1100 sent, in 0.1 mm steps (-1 before the first TPDO2).
  std::int32_t position_steps() const { return position_; }

 private:
  void step(vplant::Time now);
  void on_frame(const vplant::Frame& f, vplant::Time now);
  void fail(std::string why);

  Config config_;
  vplant::Endpoint* bus_ = nullptr;
  Phase phase_ = Phase::Booting;
  vplant::Time next_sync_{-1};
  vplant::Time settle_until_{};
  vplant::Time active_at_{};
  vplant::Time reached_at_{};
  std::int32_t position_ = -1;
  std::string failure_;
};

}  // namespace example
