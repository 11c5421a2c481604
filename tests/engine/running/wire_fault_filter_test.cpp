// Wire-fault rules are freed when they end (removed, or their count ran out), so a long run that
// added and removed many rules filters each frame at the cost of the rules still in force (issue 25).
#include "engine/running/wire_fault_filter.h"

#include <gtest/gtest.h>

#include <vector>

namespace {

scenario::WireFault drop(std::uint32_t id, std::uint64_t count = 0) {
  scenario::WireFault w;
  w.match.id = id;
  w.kind = scenario::WireFault::Kind::Drop;
  w.count = count;
  return w;
}

TEST(WireFaultFilter, RemovedRulesAreFreed) {
  scenario::Random random(1);
  scenario::WireFaultFilter filter(&random);
  std::vector<int> handles;
  for (int i = 0; i < 1000; ++i) handles.push_back(filter.add(drop(0x100)));
  const int kept = filter.add(drop(0x200));
  EXPECT_EQ(filter.active(), 1001u);
  for (const int h : handles) filter.remove(h);
  EXPECT_EQ(filter.active(), 1u);
  filter.remove(handles.front());  // twice: ignored, the other rule stays
  EXPECT_EQ(filter.active(), 1u);
  auto f = sim::CanFrame::data_frame(0x100, {1});
  EXPECT_FALSE(filter.on_send(f, 0, sim::Time{}).drop);
  f = sim::CanFrame::data_frame(0x200, {1});
  EXPECT_TRUE(filter.on_send(f, 0, sim::Time{}).drop);
  filter.remove(kept);
  EXPECT_EQ(filter.active(), 0u);
}

TEST(WireFaultFilter, ARuleWhoseCountRanOutIsFreed) {
  scenario::Random random(1);
  scenario::WireFaultFilter filter(&random);
  const int h = filter.add(drop(0x100, 2));
  auto f = sim::CanFrame::data_frame(0x100, {1});
  EXPECT_TRUE(filter.on_send(f, 0, sim::Time{}).drop);
  EXPECT_TRUE(filter.on_send(f, 0, sim::Time{}).drop);
  EXPECT_EQ(filter.active(), 0u);
  EXPECT_FALSE(filter.on_send(f, 0, sim::Time{}).drop);
  filter.remove(h);  // its owner clears it later: nothing left to do
  EXPECT_EQ(filter.active(), 0u);
}

}  // namespace
