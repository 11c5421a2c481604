// Receive and transmit PDOs (CiA 301 §7.2.2): communication parameters (0x1400+/0x1800+),
// mapping (0x1600+/0x1A00+) with the dynamic-mapping procedure and its aborts, and every
// transmission type: 0 (acyclic synchronous), 1-240 (every n-th SYNC), 252/253 (RTR only),
// 254/255 (event-driven, inhibit time, event timer).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "devices/canopen/entry_ref.h"
#include "devices/canopen/node_policy.h"
#include "devices/canopen/pdo_mapping.h"
#include "devices/canopen/service_links.h"
#include "sim/can_frame.h"
#include "sim/time.h"

namespace canopen {

class PdoService {
 public:
  /// `status`: NMT state and time; `events`: RPDO received / TPDO about to be sampled (for the
  /// application); `emcy`: RPDO length (8210h/8220h) and deadline (8250h) errors; `routes`: a
  /// PDO's COB-ID or validity changed.
  PdoService(ObjectDictionary& od, const PdoPolicy& policy, const NodeStatus& status, FrameSender& sender,
             PdoEvents& events, EmcyRequests& emcy, RoutesChanged& routes);

  /// Finds the PDO objects in the dictionary and installs their write checks.
  void bind_objects();
  /// Re-reads every PDO's parameters and mapping (after a reset or a device-made mapping change).
  void reload();

  int rpdo_count() const { return static_cast<int>(rpdos_.size()); }
  int tpdo_count() const { return static_cast<int>(tpdos_.size()); }
  /// COB-IDs to route (valid PDOs only).
  struct Route {
    std::uint32_t cob_id;
    bool extended;
    int number;  // 1-based
  };
  std::vector<Route> rpdo_routes() const;
  std::vector<Route> tpdo_routes() const;  ///< for remote requests

  void on_rpdo(int number, const sim::CanFrame& frame, sim::Time now);
  void on_tpdo_rtr(int number, const sim::CanFrame& frame, sim::Time now);
  /// `counter`: the SYNC counter (1..0x1019), or 0 when SYNCs carry none.
  void on_sync(std::uint8_t counter, sim::Time now);
  void on_enter_operational(sim::Time now);
  /// Application event for TPDO n (types 0 and 254/255): sends now (or at the next SYNC for
  /// type 0), subject to the inhibit time.
  void request_tpdo(int number);
  /// Restarts TPDO n's event timer from now (e.g. a device whose timer object was rewritten).
  void restart_event_timer(int number);
  /// Minimum spacing the device itself imposes on TPDO n, on top of its inhibit time (e.g. a
  /// profile's cyclic timer that paces change-driven transmission). 0 = none.
  void set_min_spacing(int number, sim::Duration spacing);
  /// The device switches PDO n off (or on again) whatever its COB-ID says: CiA 408 products whose
  /// fixed mapping depends on the control mode listen to one RPDO and send one TPDO only, while
  /// the others still read back as valid. Default: active.
  void set_active(PdoDirection dir, int number, bool active);
  bool active(PdoDirection dir, int number) const;
  void process(sim::Time now);

  /// Current mapped length of TPDO/RPDO n (for tests and tools).
  int tpdo_length(int number) const;
  int rpdo_length(int number) const;

 private:
  struct Pdo {
    int number = 0;
    std::uint16_t comm_index = 0;
    std::uint16_t map_index = 0;
    bool valid = false;            ///< COB-ID valid and not switched off by the device
    bool device_disabled = false;  ///< set_active(false)
    bool extended = false;
    bool rtr_allowed = true;
    std::uint32_t cob_id = 0;
    std::uint8_t type = 255;
    PdoMapping mapping;
    // Communication sub 3 (inhibit time) and 5 (event timer), read every tick; null when absent.
    EntryRef<std::uint16_t> inhibit_time;
    EntryRef<std::uint16_t> event_timer;
  };
  struct Rpdo : Pdo {
    bool latched = false;
    std::array<std::uint8_t, 8> buffer{};
    bool deadline_armed = false;
    sim::Time last_rx{};
  };
  struct Tpdo : Pdo {
    std::uint8_t sync_count = 0;
    std::uint8_t sync_start = 0;     ///< sub 6: first SYNC counter value that counts (0 = any)
    bool awaiting_start = true;      ///< types 1-240: no SYNC has counted since Operational
    bool sent_once = false;
    bool event_pending = false;     ///< triggered, waiting for the inhibit time (or SYNC for type 0)
    sim::Time inhibit_until{};
    sim::Time next_timer{};
    std::array<std::uint8_t, 8> last_sent{};
    sim::Duration min_spacing{0};
    std::array<std::uint8_t, 8> sampled{};   ///< type 252: sampled at SYNC
    bool has_sample = false;
  };

  /// TPDOs by position in tpdos_, ascending: those on_sync() acts on (valid, mapped, type 0-240
  /// or 252) and those process() acts on (valid, mapped, type 254/255). Rebuilt after every
  /// load() (reload(), set_active()): those are the only places a TPDO's validity, mapping or type
  /// change, so walking a list visits exactly the TPDOs a walk over all of them would act on.
  void rebuild_lists();
  template <typename Visit>
  void walk(const std::vector<std::uint16_t>& list, Visit&& visit);
  void load(Pdo& p, PdoDirection dir);
  /// Resolves p's mapping (mapping object sub 0 and its entries) into p.mapping.
  void resolve(Pdo& p, PdoDirection dir);
  /// The mapped entries and the bound communication entries point into the dictionary: when its
  /// object set changed since they were resolved (an entry removed or replaced while mapped),
  /// every PDO resolves them again before it touches one. One compare on each entry point.
  void follow_layout() {
    if (od_.layout() != layout_) relink();
  }
  void relink();
  void bind_timers(Pdo& p);
  void load(Tpdo& t);  ///< load(t, Transmit) plus the TPDO-only SYNC start value
  void install_checks(std::uint16_t comm_index, std::uint16_t map_index, PdoDirection dir);
  void apply_rpdo(Rpdo& p);
  void sample(Tpdo& t, std::array<std::uint8_t, 8>& out);
  void transmit(Tpdo& t, const std::array<std::uint8_t, 8>& data, sim::Time now);
  std::uint8_t wire_length(const Tpdo& t) const;  ///< DLC on the bus: the mapped length, or 8 padded
  void try_send_event(Tpdo& t, sim::Time now);
  const PdoPolicy::AsyncTriggers* async_triggers(const Tpdo& t) const;
  std::uint16_t event_timer_ms(const Pdo& p) const;
  std::uint16_t inhibit_100us(const Pdo& p) const;
  MappingRules rules() const;

  ObjectDictionary& od_;
  const PdoPolicy& policy_;
  const NodeStatus& status_;
  FrameSender& sender_;
  PdoEvents& events_;
  EmcyRequests& emcy_;
  RoutesChanged& routes_;
  std::vector<Rpdo> rpdos_;
  std::vector<Tpdo> tpdos_;
  std::vector<std::uint16_t> sync_tpdos_;
  std::vector<std::uint16_t> async_tpdos_;
  std::uint64_t layout_ = 0;          ///< od_.layout() the pointers were resolved under
  std::uint32_t lists_version_ = 0;  ///< bumped by rebuild_lists(): a walk notices a rebuild under it
  bool any_latched_ = false;         ///< some RPDO may be latched for the next SYNC
  bool any_deadline_armed_ = false;  ///< some RPDO may have its reception deadline armed
};

}  // namespace canopen
