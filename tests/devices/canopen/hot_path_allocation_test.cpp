// Nothing allocates per frame: once a node runs, receiving and answering SYNC, RPDOs, SDO
// requests (expedited and segmented) and sending TPDOs, heartbeats and SDO replies makes no heap
// allocation - not in the stack, not on the bus, not in the scheduler.
// (tests/support/counting_allocator.h says what is counted.)
#include <gtest/gtest.h>

#include <array>

#include "devices/canopen/node.h"
#include "sim/bus.h"
#include "sim/scheduler.h"
#include "tests/devices/canopen/generic_node.h"
#include "tests/support/counting_allocator.h"

namespace {

// The master's side: counts what node 5 sends, by COB-ID, in a fixed table (no allocation).
struct CountingMaster : sim::FrameReceiver {
  std::array<long, 0x800> by_id{};
  std::array<std::uint8_t, 8> last_sdo{};  ///< the last SDO reply
  void on_frame(const sim::CanFrame& f, sim::Time) override {
    if (f.extended || f.id >= by_id.size()) return;
    ++by_id[f.id];
    if (f.id == 0x585) last_sdo = f.data;
  }
};

TEST(HotPath, ServingFramesDoesNotAllocate) {
  const long at_start = vtest::allocation_count();
  canopen::Node node("node5", vtest::make_generic_od(), {}, 5);
  ASSERT_GT(vtest::allocation_count() - at_start, 100) << "the counting hook must see the node being built";
  sim::Bus bus("main");
  CountingMaster master;
  const int master_ep = bus.attach(&master);
  node.attach(bus);
  sim::Scheduler scheduler;
  scheduler.add_bus(&bus);
  scheduler.add(&node);
  node.power_on(scheduler.now());
  scheduler.run_ticks(1);

  auto send = [&](std::uint32_t id, std::initializer_list<std::uint8_t> bytes) {
    bus.send(master_ep, sim::CanFrame::data_frame(id, bytes), scheduler.now());
    scheduler.deliver_all();
  };
  send(0x605, {0x2B, 0x17, 0x10, 0x00, 10, 0, 0, 0});     // heartbeat every 10 ms
  send(0x605, {0x2B, 0x00, 0x18, 0x05, 5, 0, 0, 0});      // TPDO1 event timer 5 ms
  send(0x000, {0x01, 0x05});                              // NMT start
  // One tick of traffic: SYNC (TPDO2 answers), an RPDO that changes TPDO1's data, an expedited
  // upload and download, and every 10th tick a whole segmented upload of a 21-byte string.
  auto traffic = [&](int k) {
    send(0x080, {});
    send(0x205, {static_cast<std::uint8_t>(k), 0, 0, 0, static_cast<std::uint8_t>(k >> 3), 0});
    send(0x605, {0x40, 0x01, 0x60, 0x00, 0, 0, 0, 0});
    send(0x605, {0x2F, 0x00, 0x20, 0x00, static_cast<std::uint8_t>(k), 0, 0, 0});
    if (k % 10 == 0) {
      send(0x605, {0x40, 0x02, 0x20, 0x00, 0, 0, 0, 0});
      for (std::uint8_t segment : {0x60, 0x70, 0x60}) send(0x605, {segment, 0, 0, 0, 0, 0, 0, 0});
      EXPECT_EQ(master.last_sdo[0], 0x01);  // toggle 0, all 7 bytes valid, last segment
    }
    scheduler.run_ticks(1);
  };
  for (int k = 0; k < 100; ++k) traffic(k);  // warm-up: buffers reach their working size

  const auto before = master.by_id;
  const long allocations_before = vtest::allocation_count();
  constexpr int kTicks = 2000;
  for (int k = 0; k < kTicks; ++k) traffic(k);
  const long allocations = vtest::allocation_count() - allocations_before;

  // The traffic really happened: every SYNC answered, every SDO request answered, heartbeats.
  EXPECT_EQ(master.by_id[0x285] - before[0x285], kTicks);
  EXPECT_EQ(master.by_id[0x585] - before[0x585], 2 * kTicks + kTicks / 10 * 4);  // 21 bytes: initiate + 3 segments
  EXPECT_GE(master.by_id[0x185] - before[0x185], kTicks / 5);
  EXPECT_GE(master.by_id[0x705] - before[0x705], kTicks / 10);
  EXPECT_EQ(node.od().get<std::uint8_t>(0x2000), static_cast<std::uint8_t>(kTicks - 1));
  EXPECT_EQ(allocations, 0);
}

}  // namespace
