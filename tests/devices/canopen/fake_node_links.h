// What a node hands its CiA 301 services (devices/canopen/service_links.h), faked: the status a
// test sets by hand, and every frame sent and event raised recorded. A service built with it has
// no Node above it, which is what its "wired from above" test proves.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "devices/canopen/service_links.h"
#include "tests/support/canopen_harness.h"

namespace vtest {

struct FakeNodeLinks final : canopen::FrameSender,
                             canopen::RoutesChanged,
                             canopen::EmcyRequests,
                             canopen::NmtCommandHandler,
                             canopen::SyncEvents,
                             canopen::PdoEvents,
                             canopen::CommErrorEvents,
                             canopen::SilenceRequest,
                             canopen::LssEvents {
  canopen::NodeStatus status;

  Frames sent;
  int routes_changed = 0;
  std::vector<std::uint16_t> raised;
  std::vector<std::uint16_t> cleared;
  std::vector<canopen::NmtCommand> nmt_commands;
  std::vector<std::pair<std::uint8_t, std::uint8_t>> syncs;  ///< (PDO counter, device counter)
  std::vector<int> rpdos;
  std::vector<int> tpdo_samples;
  std::vector<std::pair<canopen::CommError, std::uint32_t>> comm_errors;
  std::vector<canopen::CommError> comm_recoveries;
  sim::Time silent_until{};
  std::vector<std::uint8_t> pending_node_ids;
  int node_id_applied = 0;

  void send(const sim::CanFrame& frame) override { sent.push_back(Frame::from(frame)); }
  void rebuild_dispatch() override { ++routes_changed; }
  void raise_emcy(std::uint16_t code) override { raised.push_back(code); }
  void clear_emcy(std::uint16_t code) override { cleared.push_back(code); }
  void execute_nmt(canopen::NmtCommand command, std::string_view) override { nmt_commands.push_back(command); }
  void sync_received(std::uint8_t pdo_counter, std::uint8_t counter, sim::Time) override {
    syncs.emplace_back(pdo_counter, counter);
  }
  void rpdo_received(int number) override { rpdos.push_back(number); }
  void before_tpdo(int number) override { tpdo_samples.push_back(number); }
  void communication_error(canopen::CommError error, std::uint32_t evidence) override {
    comm_errors.emplace_back(error, evidence);
  }
  void communication_recovered(canopen::CommError error) override { comm_recoveries.push_back(error); }
  void go_silent_until(sim::Time until) override { silent_until = until; }
  void set_pending_node_id(std::uint8_t id) override {
    status.pending_node_id = id;
    pending_node_ids.push_back(id);
  }
  void apply_pending_node_id() override { ++node_id_applied; }
};

}  // namespace vtest
