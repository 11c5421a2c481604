// A verdict on the master under test: taps every bus, follows the frames that no emulated node
// sent (the scripted master, a library endpoint, a socketcand or SocketCAN client) and what the
// nodes make of them, and records a finding whenever a named rule (master_rules.h) is broken:
// a request before the node's boot-up, an SDO the node aborted or never answered, SDO protocol
// errors, NMT to an unknown node, PDO configuration while the PDO is valid, RPDOs of the wrong
// length, a device fault after a master action, the nodes' heartbeat consumers and life guarding
// timing out on the master, SYNC off 1006h. Runs on the scheduler's thread after the nodes and
// allocates nothing there (findings go to a bounded FindingLog).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string_view>
#include <vector>

#include "sim/bus.h"
#include "sim/scheduler.h"
#include "engine/running/master_findings.h"
#include "engine/loading/master_rules.h"

namespace canopen {
class Node;
class OdEntry;
}
namespace devices {
class Device;
}

namespace scenario {

class World;
class FaultInjector;

class MasterMonitor final : public sim::Steppable {
 public:
  static constexpr std::size_t kDefaultCapacity = 1024;
  /// An SDO request not answered within this is `sdo-no-answer`.
  static constexpr sim::Duration kSdoTimeout = sim::milliseconds(1000);
  /// A device fault counts against the master action to that node at most this long before.
  static constexpr sim::Duration kActionWindow = sim::milliseconds(1000);
  /// Heartbeat consumers and life guarding are looked at this often,
  static constexpr sim::Duration kPollPeriod = sim::milliseconds(10);
  /// the device state machines this often (a fault state lasts until the master resets it).
  static constexpr int kStatePollEvery = 5;

  /// Taps every bus of `world`. `faults` (may be null): a fault the scenario injects is not the
  /// master's doing, so device faults within kActionWindow after one are not counted.
  MasterMonitor(World& world, const MasterRuleSettings& rules, sim::Duration tick, const FaultInjector* faults = nullptr,
                std::size_t capacity = kDefaultCapacity);
  ~MasterMonitor() override;
  MasterMonitor(const MasterMonitor&) = delete;
  MasterMonitor& operator=(const MasterMonitor&) = delete;

  void step(sim::Time now, sim::Duration dt) override;

  const FindingLog& findings() const { return log_; }
  const MasterRuleSettings& rules() const { return rules_; }
  const std::vector<std::string>& bus_names() const { return bus_names_; }

 private:
  class Tap;
  enum class Transfer : std::uint8_t { Idle, Download, Upload, Block };
  struct SdoWatch {
    Transfer transfer = Transfer::Idle;
    bool toggle = false;             ///< the toggle bit the next segment request must carry
    bool size_known = false;
    std::uint32_t size = 0;          ///< indicated by a segmented download's initiate
    std::uint32_t sent = 0;          ///< bytes of the segments so far
    bool awaiting = false;           ///< a request waits for the server's answer
    bool block_download = false;     ///< Block: a block download (else an upload)
    std::uint16_t index = 0;         ///< the object of the transfer
    std::uint8_t sub = 0;
    sim::Time since{};
    Evidence request;                ///< the last request (evidence of an abort or silence)
  };
  struct Action {
    bool valid = false;
    Evidence frame;
  };
  struct ChannelState {
    bool fault = false;
    std::string_view state;  ///< at the last look (static text)
  };
  struct NodeWatch {
    canopen::Node* node = nullptr;
    devices::Device* device = nullptr;
    int bus = 0;
    std::uint8_t id = 0;           ///< the node-ID its frames carry now
    bool booted = false;           ///< boot-up seen since the last reset
    bool early_reported = false;   ///< before-boot-up already reported for this reset
    Action reset;                  ///< the master's last reset of this node
    Action command;                ///< last NMT or SDO request to it
    Action rpdo;                   ///< last RPDO to it
    int channels = 0;              ///< profile state machines (0: the device's only one)
    std::array<ChannelState, 5> state{};
    bool heartbeat_timed_out = false;
    bool guarding_error = false;
    sim::Time last_rpdo_finding{};
    bool rpdo_finding_seen = false;
  };
  struct BusWatch {
    sim::Bus* bus = nullptr;
    std::vector<char> node_endpoint;          ///< by endpoint id: an emulated node sent it
    std::vector<int> watch_of_endpoint;       ///< by endpoint id: index into nodes_ or -1
    std::array<int, 128> watch_of_id{};       ///< by node-ID: index into nodes_ or -1
    std::array<SdoWatch, 128> sdo{};
    /// 1006h of the bus's nodes that have one (entries stay put): read on every SYNC.
    std::vector<std::pair<std::uint8_t, const canopen::OdEntry*>> cycle_periods;
    bool sync_seen = false;
    Evidence last_sync;
    sim::Time last_jitter_finding{};
    bool jitter_reported = false;
  };

  void on_frame(int bus, const sim::CanFrame& f, sim::Time now);
  void on_master_frame(BusWatch& b, int bus, const sim::CanFrame& f, sim::Time now);
  void on_node_frame(BusWatch& b, int bus, int watch, const sim::CanFrame& f, sim::Time now);
  void master_nmt(BusWatch& b, int bus, const Evidence& e);
  void master_sdo(BusWatch& b, int bus, std::uint8_t id, const Evidence& e);
  void master_rpdo(int bus, const Evidence& e);
  void master_sync(BusWatch& b, int bus, const Evidence& e);
  void server_sdo(BusWatch& b, int bus, std::uint8_t id, const Evidence& e);
  void check_pdo_config(NodeWatch& w, int bus, const Evidence& e, std::uint16_t index, std::uint8_t sub);
  void early(NodeWatch& w, int bus, const Evidence& e, const char* what);
  void poll_devices(sim::Time now);
  void poll_sdo_timeouts(sim::Time now);
  void poll_device_state(NodeWatch& w, int channel, sim::Time now);
  NodeWatch* watch_at(BusWatch& b, std::uint8_t id);

  /// Records a finding (unless the rule is off); `format` is printf-style.
  Finding* report(MasterRule rule, sim::Time t, int bus, int node, std::initializer_list<const Evidence*> evidence,
                  const char* format, ...) __attribute__((format(printf, 7, 8)));

  World& world_;
  MasterRuleSettings rules_;
  sim::Duration tick_;
  const FaultInjector* faults_;
  FindingLog log_;
  std::vector<std::string> bus_names_;
  std::vector<std::unique_ptr<Tap>> taps_;
  std::vector<BusWatch> buses_;
  std::vector<NodeWatch> nodes_;
  std::size_t awaiting_ = 0;  ///< SDO requests waiting for an answer, all buses
  sim::Time next_poll_{};
  int polls_ = 0;
  std::size_t faults_seen_ = 0;
  sim::Time last_fault_{};
  bool fault_seen_ = false;
};

}  // namespace scenario
