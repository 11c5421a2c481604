#include "devices/canopen/store_restore.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>

#include "tests/devices/canopen/fake_node_links.h"
#include "tests/devices/canopen/generic_node.h"
#include "tests/support/canopen_harness.h"
#include "tests/support/temp_path.h"

using vtest::Frame;
using vtest::Frames;

namespace {
std::string temp_path() { return vtest::unique_temp_path("vplant-store"); }
constexpr std::uint32_t kSave = 0x65766173, kLoad = 0x64616F6C;
}  // namespace

TEST(StoreRestore, SaveSurvivesPowerCycleAndRestoreReturnsDefaults) {
  canopen::NodePolicy p;
  p.store.path = temp_path();
  vtest::CanopenHarness h(vtest::make_generic_od(), p, 5);
  h.power_on();
  ASSERT_EQ(h.write(0x2000, 0, 42, 1), 0u);
  ASSERT_EQ(h.write(0x1017, 0, 500, 2), 0u);
  EXPECT_EQ(h.write(0x1010, 1, 0x12345678, 4), 0x08000020u);  // wrong signature
  ASSERT_EQ(h.write(0x1010, 1, kSave, 4), 0u);
  EXPECT_EQ(h.read_u(0x1010, 1), 1u);  // reads the capability, not the signature
  h.node().power_off();
  h.power_on();
  EXPECT_EQ(h.node().od().get<int>(0x2000), 42);
  EXPECT_EQ(h.node().od().get<int>(0x1017), 500);
  // Restore: the values in use stay until the next reset.
  ASSERT_EQ(h.write(0x1011, 1, kLoad, 4), 0u);
  EXPECT_EQ(h.node().od().get<int>(0x2000), 42);
  h.nmt(0x81, 5);
  h.run_ticks(1);
  EXPECT_EQ(h.node().od().get<int>(0x2000), 7);
  EXPECT_EQ(h.node().od().get<int>(0x1017), 0);
  std::remove(p.store.path.c_str());
}

TEST(StoreRestore, WithoutAFileSavedValuesSurviveAPowerCycleInTheRun) {
  vtest::CanopenHarness h(vtest::make_generic_od(), {}, 5);
  h.power_on();
  ASSERT_EQ(h.write(0x2000, 0, 42, 1), 0u);
  ASSERT_EQ(h.write(0x1010, 1, kSave, 4), 0u);
  ASSERT_EQ(h.write(0x2000, 0, 43, 1), 0u);
  h.node().power_off();
  h.power_on();
  EXPECT_EQ(h.node().od().get<int>(0x2000), 42);
}

TEST(StoreRestore, GroupsSaveOnlyTheirArea) {
  canopen::NodePolicy p;
  vtest::CanopenHarness h(vtest::make_generic_od(), p, 5);
  h.power_on();
  ASSERT_EQ(h.write(0x2000, 0, 42, 1), 0u);
  ASSERT_EQ(h.write(0x1017, 0, 500, 2), 0u);
  ASSERT_EQ(h.write(0x1010, 2, kSave, 4), 0u);  // communication only
  h.nmt(0x81, 5);
  h.run_ticks(1);
  EXPECT_EQ(h.node().od().get<int>(0x2000), 7);
  EXPECT_EQ(h.node().od().get<int>(0x1017), 500);
}

TEST(StoreRestore, NodeRelativeCobIdsFollowANewNodeId) {
  canopen::NodePolicy p;
  vtest::CanopenHarness h(vtest::make_generic_od(), p, 5);
  h.power_on();
  ASSERT_EQ(h.write(0x1010, 1, kSave, 4), 0u);
  h.node().set_pending_node_id(9);
  h.nmt(0x82, 5);
  h.run_ticks(1);
  EXPECT_EQ(h.take().back(), Frame(0x709, {0x00}));
  EXPECT_EQ(h.node().od().get<std::uint32_t>(0x1800, 1), 0x189u);
}

TEST(StoreRestore, PresetValuesApplyAtEveryPowerOnLikeStoredOnes) {
  canopen::NodePolicy p;
  p.store.preset = {{0x1017, 0, {0xF4, 0x01}}, {0x2000, 0, {0x2A}}};
  vtest::CanopenHarness h(vtest::make_generic_od(), p, 5);
  h.power_on();
  EXPECT_EQ(h.node().od().get<int>(0x1017), 500);
  EXPECT_EQ(h.node().od().get<int>(0x2000), 42);
  ASSERT_EQ(h.write(0x2000, 0, 7, 1), 0u);
  h.node().power_off();
  h.power_on();  // the preset is back after a power cycle
  EXPECT_EQ(h.node().od().get<int>(0x2000), 42);
  // Restore defaults erases it like any stored value: defaults after the next reset.
  ASSERT_EQ(h.write(0x1011, 1, kLoad, 4), 0u);
  h.nmt(0x81, 5);
  h.run_ticks(1);
  EXPECT_EQ(h.node().od().get<int>(0x2000), 7);
  EXPECT_EQ(h.node().od().get<int>(0x1017), 0);
}

TEST(StoreRestore, FailingMemoryAborts06060000) {
  vtest::CanopenHarness h(vtest::make_generic_od(), {}, 5);
  h.power_on();
  h.node().store().set_failing(true);
  EXPECT_EQ(h.write(0x1010, 1, kSave, 4), 0x06060000u);
}

TEST(ParameterStore, KillDuringSaveLeavesOldOrNewSetNeverTorn) {
  const std::string path = temp_path();
  canopen::ParameterStore store(path);
  store.put(0x2000, 0, {false, {1}});
  std::string error;
  ASSERT_TRUE(store.save(error)) << error;
  // Children write a large new set and are killed at random moments; the file always parses
  // and holds either the complete old or the complete new set. The last round is killed only
  // once the new set is in the file, so the test also shows that a save completes whole.
  bool saw_new = false;
  for (int round = 0; round < 21; ++round) {
    const bool last = round == 20;
    const pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      canopen::ParameterStore big(path);
      for (int i = 0; i < 5000; ++i) big.put(static_cast<std::uint16_t>(0x2000 + i), 0, {false, {2, 2, 2, 2}});
      for (;;) {
        std::string e;
        big.save(e);
      }
    }
    if (last) {
      for (int wait_ms = 0; wait_ms < 20000; ++wait_ms) {
        canopen::ParameterStore probe(path);
        std::string e;
        if (probe.load(e) && probe.values().size() == 5000) break;
        usleep(1000);
      }
    } else {
      usleep(static_cast<useconds_t>(200 + round * 150));
    }
    kill(pid, SIGKILL);
    int status = 0;
    waitpid(pid, &status, 0);
    canopen::ParameterStore check(path);
    ASSERT_TRUE(check.load(error)) << error;
    const auto n = check.values().size();
    EXPECT_TRUE(n == 1 || n == 5000) << n;
    saw_new = saw_new || n == 5000;
  }
  EXPECT_TRUE(saw_new);
  std::remove(path.c_str());
  std::remove((path + ".tmp").c_str());
}

TEST(ParameterStore, MalformedFileIsReportedWithLine) {
  const std::string path = temp_path();
  {
    std::ofstream f(path);
    f << "# vplant parameter store v1\n2000:00=01\nbogus line\n";
  }
  canopen::ParameterStore store(path);
  std::string error;
  EXPECT_FALSE(store.load(error));
  EXPECT_NE(error.find(path + ":3:"), std::string::npos) << error;
  EXPECT_TRUE(store.values().empty());
  std::remove(path.c_str());
}

TEST(StoreRestore, RestoreCanBeSilentAndTheHardwareAbortIsConfigurable) {
  canopen::NodePolicy p;
  p.store.restore_busy_time = sim::milliseconds(3000);
  p.store.hardware_error = static_cast<canopen::SdoAbort>(0x06000006);
  vtest::CanopenHarness h(vtest::make_generic_od(), p, 5);
  h.power_on();
  h.take();
  h.send(0x605, {0x23, 0x11, 0x10, 0x01, 0x6C, 0x6F, 0x61, 0x64});
  EXPECT_TRUE(h.take().empty());
  h.send(Frame::remote(0x705, 1));
  h.run_ms(2990);
  EXPECT_TRUE(h.take().empty());
  h.run_ms(20);
  EXPECT_EQ(h.take(), Frames{Frame(0x585, {0x60, 0x11, 0x10, 0x01, 0, 0, 0, 0})});
  h.node().store().set_failing(true);
  EXPECT_EQ(h.write(0x1010, 1, kSave, 4), 0x06000006u);
}

// Values in the store file go through the checks of an SDO download: each one refused is
// reported as file:line and the entry keeps its default; the valid ones load.
TEST(StoreRestore, StoredValuesAreCheckedLikeAnSdoWrite) {
  const vtest::TempPath path("vplant-store-values");
  {
    std::ofstream f(path.str());
    f << "# vplant parameter store v1\n"
         "1000:00=00000000\n"       // 2: read-only device type
         "1017:00=F401\n"           // 3: valid, 500 ms
         "1800:02=$NODEID+FF\n"     // 4: 0xFF + 5 overflows UNSIGNED8
         "1800:07=01\n"             // 5: no such sub-index
         "2000:00=FF\n"             // 6: 255, the limit is 200
         "2005:00=00000000\n"       // 7: constant
         "2006:00=0102\n"           // 8: 2 bytes for an UNSIGNED64
         "3000:00=01\n";            // 9: no such object
  }
  canopen::NodePolicy p;
  p.store.path = path;
  auto od = vtest::make_generic_od();
  od.entry(0x2000, 0)->low_limit = canopen::Bytes{1};
  od.entry(0x2000, 0)->high_limit = canopen::Bytes{200};
  vtest::CanopenHarness h(std::move(od), p, 5);
  h.power_on();
  const auto& od_now = h.node().od();
  EXPECT_EQ(od_now.get<std::uint32_t>(0x1000), 0x191u);
  EXPECT_EQ(od_now.get<int>(0x1017), 500);
  EXPECT_EQ(od_now.get<int>(0x1800, 2), 255);  // its default
  EXPECT_EQ(od_now.get<int>(0x2000), 7);
  EXPECT_EQ(od_now.get<std::uint32_t>(0x2005), 0x01020304u);
  EXPECT_EQ(od_now.get<std::uint64_t>(0x2006), 0x1122334455667788ull);
  const std::string& f = path.str();
  const std::vector<std::string> expected = {
      f + ":2: 1000h sub 0 is read-only",
      f + ":4: $NODEID+255 overflows UNSIGNED8 with node-ID 5 (1800h sub 2)",
      f + ":5: 1800h sub 7: no such sub-index",
      f + ":6: value 255 of 2000h sub 0 is above its high limit 200",
      f + ":7: 2005h sub 0 is constant",
      f + ":8: 2-byte value for 2006h sub 0 (UNSIGNED64, 8 bytes)",
      f + ":9: 3000h sub 0: no such object",
  };
  auto rejected = h.node().store().rejected();  // in load order: application area first
  std::sort(rejected.begin(), rejected.end());
  EXPECT_EQ(rejected, expected);
  // An NMT reset loads the store again but reports nothing twice.
  h.nmt(0x81, 5);
  h.run_ticks(1);
  EXPECT_EQ(h.node().store().rejected().size(), expected.size());
  EXPECT_EQ(h.node().od().get<int>(0x1017), 500);
}

TEST(ParameterStore, AMalformedLineIsPrintedEscaped) {
  const vtest::TempPath path("vplant-store-escape");
  std::ofstream(path.str()) << "# vplant parameter store v1\n2000:00=\x1b[2J\x07\xff\n";
  canopen::ParameterStore store(path);
  std::string error;
  ASSERT_FALSE(store.load(error));
  EXPECT_EQ(error, path.str() + ":2: malformed value '\\x1B[2J\\x07\\xFF' (expected pairs of hex digits)");
}

TEST(ParameterStore, OnlyARegularFileIsReadAndNeverBlocks) {
  const vtest::TempPath dir("vplant-store-dir");
  ASSERT_EQ(::mkdir(dir.c_str(), 0700), 0);
  std::string error;
  EXPECT_FALSE(canopen::ParameterStore(dir).load(error));
  EXPECT_EQ(error, dir.str() + ": not a regular file (a directory)");

  const std::string fifo = dir.str() + "/fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);  // no writer: a blocking open() would never return
  EXPECT_FALSE(canopen::ParameterStore(fifo).load(error));
  EXPECT_EQ(error, fifo + ": not a regular file (a FIFO)");

  EXPECT_FALSE(canopen::ParameterStore("/dev/zero").load(error));
  EXPECT_EQ(error, "/dev/zero: not a regular file (a character device)");
}

TEST(StoreRestore, WiredFromAboveAsksForSilenceWhileSaving) {
  vtest::FakeNodeLinks links;
  links.status.node_id = 5;
  links.status.now = sim::Time{} + sim::milliseconds(1000);
  auto od = vtest::make_generic_od();
  canopen::StorePolicy policy;
  policy.busy_time = sim::milliseconds(50);
  canopen::StoreRestore store(od, policy, links.status, "node", links);
  store.bind_objects();
  od.set<std::uint8_t>(0x2000, 0, 42);
  EXPECT_EQ(store.save_group(1), canopen::SdoAbort::None);
  EXPECT_EQ(links.silent_until, sim::Time{} + sim::milliseconds(1050));
  ASSERT_NE(store.memory().find(0x2000, 0), nullptr);
  EXPECT_EQ(store.memory().find(0x2000, 0)->bytes, canopen::Bytes{42});
}
