// devices/transition_log.h: a bounded history, oldest first, read after a seq number; when full
// the oldest entries go and the seq numbers show the gap.
#include "devices/transition_log.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace devices {
namespace {

Transition entry(std::uint64_t t_us, std::uint32_t value) {
  Transition t;
  t.t_us = t_us;
  t.machine = "nmt";
  t.value = value;
  return t;
}

std::vector<std::uint64_t> seqs_after(const TransitionLog& log, std::uint64_t after) {
  std::vector<std::uint64_t> out;
  log.for_each_after(after, [&](const Transition& t) { out.push_back(t.seq); });
  return out;
}

TEST(TransitionLog, KeepsOrderAndReadsAfterASeq) {
  TransitionLog log;
  EXPECT_TRUE(seqs_after(log, 0).empty());
  for (std::uint64_t i = 0; i < 3; ++i) log.record(entry(10 * i, 0));
  EXPECT_EQ(log.size(), 3u);
  EXPECT_EQ(seqs_after(log, 0), (std::vector<std::uint64_t>{1, 2, 3}));
  EXPECT_EQ(seqs_after(log, 2), (std::vector<std::uint64_t>{3}));
  EXPECT_TRUE(seqs_after(log, 3).empty());
  EXPECT_TRUE(seqs_after(log, 99).empty());
}

TEST(TransitionLog, DropsTheOldestWhenFull) {
  TransitionLog log;
  const std::uint64_t n = TransitionLog::kCapacity + 10;
  for (std::uint64_t i = 1; i <= n; ++i) log.record(entry(i, static_cast<std::uint32_t>(i)));
  EXPECT_EQ(log.size(), TransitionLog::kCapacity);
  EXPECT_EQ(log.last_seq(), n);
  std::vector<std::uint64_t> kept;
  log.for_each_after(0, [&](const Transition& t) {
    EXPECT_EQ(t.value, t.seq);  // each slot holds the entry its seq names
    kept.push_back(t.seq);
  });
  ASSERT_EQ(kept.size(), TransitionLog::kCapacity);
  EXPECT_EQ(kept.front(), 11u);
  EXPECT_EQ(kept.back(), n);
  EXPECT_EQ(seqs_after(log, n - 2), (std::vector<std::uint64_t>{n - 1, n}));
  log.clear();
  EXPECT_EQ(log.size(), 0u);
}

TEST(TransitionLog, CauseNamesAreTheApiWords) {
  EXPECT_EQ(to_string(TransitionCause::ControlWord), "control_word");
  EXPECT_EQ(to_string(TransitionCause::NmtCommand), "nmt_command");
  EXPECT_EQ(to_string(TransitionCause::HeartbeatTimeout), "heartbeat_timeout");
  EXPECT_EQ(to_string(TransitionCause::Internal), "internal");
}

}  // namespace
}  // namespace devices
