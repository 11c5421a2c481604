// The verdict on the master (engine/running/master_monitor.h): each rule caught from a test master (a
// run extension with its own endpoint that sends frames at given instants, virtual time), a
// careful master and the reference plant's scripted master without findings, the scenario key,
// the report, the JUnit test cases and the bounded log.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "engine/running/master_monitor.h"
#include "engine/running/run_extension.h"
#include "engine/running/world.h"
#include "tests/engine/run_helper.h"

namespace {

using scenario::MasterRule;
using sim::CanFrame;

constexpr std::uint8_t kDsv = 2, kHlt = 5, kPump = 63, kEncoder = 127, kMaster = 100;

const std::string kNodes = R"(
name: verdict
nodes:
  - {name: dsv, device: dsv, node_id: 2, settings: {device_local: "0", control_mode: "1", mode_of_operation: "2"}}
  - {name: hlt, device: hlt1100, node_id: 5}
  - {name: pump, device: vtvpcd, node_id: 63}
  - {name: enc, device: wdga, node_id: 127}
)";

/// A master under test: sends frames at given instants from its own endpoint on the first bus.
class TestMaster final : public scenario::RunExtension, public sim::FrameReceiver {
 public:
  void at(double seconds, const CanFrame& f) { plan_.push_back({sim::kTimeZero + sim::from_seconds(seconds), f}); }
  void sdo_upload(double s, std::uint8_t node, std::uint16_t index, std::uint8_t sub) {
    at(s, CanFrame::data_frame(0x600u + node, {0x40, static_cast<std::uint8_t>(index), static_cast<std::uint8_t>(index >> 8), sub, 0, 0, 0, 0}));
  }
  void sdo_download(double s, std::uint8_t node, std::uint16_t index, std::uint8_t sub, std::uint32_t value, int size = 4) {
    at(s, CanFrame::data_frame(0x600u + node, {static_cast<std::uint8_t>(0x23 | (4 - size) << 2), static_cast<std::uint8_t>(index),
                                               static_cast<std::uint8_t>(index >> 8), sub, static_cast<std::uint8_t>(value),
                                               static_cast<std::uint8_t>(value >> 8), static_cast<std::uint8_t>(value >> 16),
                                               static_cast<std::uint8_t>(value >> 24)}));
  }
  void nmt(double s, std::uint8_t command, std::uint8_t node) { at(s, CanFrame::data_frame(0x000, {command, node})); }

  void attach(const scenario::RunContext& c) override {
    bus_ = c.world.buses()[0].get();
    scheduler_ = &c.scheduler;
    endpoint_ = bus_->attach(this);
  }
  bool before_tick(bool end) override {
    const sim::Time now = scheduler_->now();
    for (const auto& [t, f] : plan_)
      if (t == now) bus_->send(endpoint_, f, now);
    return !end;
  }
  void detach() override {}
  void on_frame(const CanFrame& f, sim::Time now) override { received_.push_back({now, f}); }
  /// The time of the first frame `id` with first byte `b0` received (for tests that wait).
  bool received(std::uint32_t id, std::uint8_t b0) const {
    for (const auto& [t, f] : received_)
      if (f.id == id && f.dlc > 0 && f.data[0] == b0) return true;
    return false;
  }

 private:
  std::vector<std::pair<sim::Time, CanFrame>> plan_;
  std::vector<std::pair<sim::Time, CanFrame>> received_;
  sim::Bus* bus_ = nullptr;
  sim::Scheduler* scheduler_ = nullptr;
  int endpoint_ = -1;
};

struct Finding {
  MasterRule rule;
  int node;
  std::string text;
  std::size_t frames;
};

struct Verdict {
  std::vector<Finding> findings;
  std::string report;  ///< --master-report JSON
  std::string junit;
  std::string output;

  std::size_t count(MasterRule rule) const {
    std::size_t n = 0;
    for (const auto& f : findings) n += f.rule == rule;
    return n;
  }
  const Finding* first(MasterRule rule) const {
    for (const auto& f : findings)
      if (f.rule == rule) return &f;
    return nullptr;
  }
  std::string all() const {
    std::string s;
    for (const auto& f : findings) s += std::string(scenario::rule_name(f.rule)) + " node " + std::to_string(f.node) + ": " + f.text + "\n";
    return s;
  }
};

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

Verdict run_master(TestMaster& master, double seconds, const std::string& extra = "") {
  const auto dir = std::filesystem::temp_directory_path() / ("vplant-verdict-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  scenario::RunOptions options;
  options.extension = &master;
  options.master_report = (dir / "report.json").string();
  options.junit = (dir / "junit.xml").string();
  std::FILE* out = std::tmpfile();
  options.out = out;
  const auto s = scenario::parse_scenario(kNodes + extra + "clock: {tick: 1ms, duration: " + std::to_string(seconds) + "s}\n",
                                          "verdict.yaml", ".");
  Verdict v;
  {
    scenario::Runner runner(s, vtest::test_environment(), options);
    runner.run();
    const auto& log = runner.master_monitor().findings();
    for (std::size_t i = 0; i < log.size(); ++i)
      v.findings.push_back({log[i].rule, log[i].node, log[i].text.data(), log[i].evidence_count});
  }
  v.report = slurp(options.master_report);
  v.junit = slurp(options.junit);
  std::rewind(out);
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, out)) > 0;) v.output.append(buf, n);
  std::fclose(out);
  std::filesystem::remove_all(dir);
  return v;
}

TEST(MasterMonitor, BeforeBootUpAfterAReset) {
  TestMaster m;
  m.nmt(1.0, 0x81, kDsv);  // reset_node, then at once an SDO: the node is still booting
  m.sdo_upload(1.0, kDsv, 0x1000, 0);
  const Verdict v = run_master(m, 3);
  ASSERT_EQ(v.count(MasterRule::BeforeBootUp), 1u) << v.all();
  const auto* f = v.first(MasterRule::BeforeBootUp);
  EXPECT_EQ(f->node, kDsv);
  EXPECT_NE(f->text.find("the master reset it at 1.000 s"), std::string::npos) << f->text;
  EXPECT_EQ(f->frames, 2u);  // the reset and the request
}

TEST(MasterMonitor, BeforeBootUpAtPowerOn) {
  TestMaster m;
  m.sdo_upload(0.0, kHlt, 0x1000, 0);  // at t = 0 no node has booted
  const Verdict v = run_master(m, 2);
  ASSERT_EQ(v.count(MasterRule::BeforeBootUp), 1u) << v.all();
  EXPECT_NE(v.first(MasterRule::BeforeBootUp)->text.find("has not booted since power-on"), std::string::npos);
}

TEST(MasterMonitor, SdoAbortNamesTheObjectAndTheCode) {
  TestMaster m;
  m.sdo_download(1.0, kDsv, 0x1000, 0, 0x12345678);  // 1000h is read-only
  const Verdict v = run_master(m, 2);
  ASSERT_EQ(v.count(MasterRule::SdoAbort), 1u) << v.all();
  const auto& text = v.first(MasterRule::SdoAbort)->text;
  EXPECT_NE(text.find("1000h:00"), std::string::npos) << text;
  EXPECT_NE(text.find("1000h:00 \"Device type\", abort code 06010000h (unsupported access to an object)"), std::string::npos) << text;
  EXPECT_NE(text.find("SDO download of 1000h:00"), std::string::npos) << text;
}

TEST(MasterMonitor, SdoNoAnswerFromAnAbsentNode) {
  TestMaster m;
  m.sdo_upload(1.0, 9, 0x1000, 0);
  const Verdict v = run_master(m, 2.5);
  ASSERT_EQ(v.count(MasterRule::SdoNoAnswer), 1u) << v.all();
  const auto* f = v.first(MasterRule::SdoNoAnswer);
  EXPECT_EQ(f->node, 9);
  EXPECT_NE(f->text.find("there is no node 9 on bus main"), std::string::npos) << f->text;
}

TEST(MasterMonitor, SdoProtocolErrors) {
  TestMaster m;
  // A download segment with no download open, an SDO frame of 5 bytes, an upload segment whose
  // toggle bit is 1 first (the encoder's device name 1008h is uploaded in segments).
  m.at(1.0, CanFrame::data_frame(0x600 + kEncoder, {0x00, 1, 2, 3, 4, 5, 6, 7}));
  m.at(1.1, CanFrame::data_frame(0x600 + kEncoder, {0x40, 0x00, 0x10, 0x00, 0}));
  m.sdo_upload(1.2, kEncoder, 0x1008, 0);
  m.at(1.3, CanFrame::data_frame(0x600 + kEncoder, {0x70, 0, 0, 0, 0, 0, 0, 0}));
  const Verdict v = run_master(m, 2);
  ASSERT_EQ(v.count(MasterRule::SdoProtocol), 3u) << v.all();
  EXPECT_NE(v.all().find("without a segmented download in progress"), std::string::npos) << v.all();
  EXPECT_NE(v.all().find("with 5 data bytes"), std::string::npos) << v.all();
  EXPECT_NE(v.all().find("toggle bit 1, expected 0"), std::string::npos) << v.all();
}

TEST(MasterMonitor, NmtToAnUnknownNode) {
  TestMaster m;
  m.nmt(1.0, 0x01, 9);
  const Verdict v = run_master(m, 1.5);
  ASSERT_EQ(v.count(MasterRule::NmtUnknownNode), 1u) << v.all();
  EXPECT_NE(v.first(MasterRule::NmtUnknownNode)->text.find("NMT start to node 9"), std::string::npos);
}

TEST(MasterMonitor, PdoConfigurationWhileValid) {
  TestMaster m;
  m.sdo_download(1.0, kPump, 0x1A00, 0, 0, 1);            // mapping of a valid TPDO1
  m.sdo_download(1.1, kPump, 0x1800, 1, 0x00000190);      // another COB-ID while valid
  m.sdo_download(1.2, kPump, 0x1801, 1, 0x800002BF);      // invalidating: what CiA 301 asks
  m.sdo_download(1.3, kPump, 0x1A01, 0, 0, 1);            // mapping of the now invalid TPDO2
  m.sdo_download(1.4, kHlt, 0x1A00, 0, 0, 1);             // read-only here: the abort says so
  const Verdict v = run_master(m, 2);
  ASSERT_EQ(v.count(MasterRule::PdoConfigWhileValid), 2u) << v.all();
  EXPECT_NE(v.all().find("the mapping of TPDO1 of node 63"), std::string::npos) << v.all();
  EXPECT_NE(v.all().find("changing the COB-ID of TPDO1 of node 63"), std::string::npos) << v.all();
}

TEST(MasterMonitor, RpdoShorterThanItsMapping) {
  TestMaster m;
  m.nmt(1.0, 0x01, 0);
  m.at(1.1, CanFrame::data_frame(0x200 + kDsv, {0x07}));
  m.at(1.2, CanFrame::data_frame(0x200 + kDsv, {0x07}));  // within a second of the first: counted once
  const Verdict v = run_master(m, 2);
  ASSERT_EQ(v.count(MasterRule::RpdoLength), 1u) << v.all();
  EXPECT_NE(v.first(MasterRule::RpdoLength)->text.find("RPDO1 of node 2 (COB-ID 202h) carried 1 byte(s)"), std::string::npos)
      << v.all();
}

TEST(MasterMonitor, DeviceFaultNamesTheMasterAction) {
  TestMaster m;
  m.nmt(1.0, 0x01, 0);
  m.at(1.1, CanFrame::data_frame(0x200 + kDsv, {0x07, 0x00, 0x00, 0x00}));  // DEVICE_MODE_ACTIVE
  m.nmt(2.0, 0x02, kDsv);                                                   // stop it while active
  const Verdict v = run_master(m, 2.5);
  ASSERT_EQ(v.count(MasterRule::DeviceFault), 1u) << v.all();
  const auto& text = v.first(MasterRule::DeviceFault)->text;
  EXPECT_NE(text.find("node 2 (dsv) entered FAULT from DEVICE_MODE_ACTIVE"), std::string::npos) << text;
  EXPECT_NE(text.find("after the master's NMT stop to node 2 at 2.000 s"), std::string::npos) << text;
}

TEST(MasterMonitor, HeartbeatConsumerTimesOutOnTheMaster) {
  TestMaster m;
  // The encoder watches the master (node 100) with 100 ms; the master beats twice, then stops.
  m.sdo_download(1.0, kEncoder, 0x1016, 1, static_cast<std::uint32_t>(kMaster) << 16 | 100);
  m.at(1.1, CanFrame::data_frame(0x700 + kMaster, {0x05}));
  m.at(1.15, CanFrame::data_frame(0x700 + kMaster, {0x05}));
  const Verdict v = run_master(m, 2);
  ASSERT_EQ(v.count(MasterRule::HeartbeatMissing), 1u) << v.all();
  EXPECT_NE(v.first(MasterRule::HeartbeatMissing)->text.find("timed out waiting for node 100, the master"), std::string::npos)
      << v.all();
}

TEST(MasterMonitor, LifeGuardingExpires) {
  TestMaster m;
  m.sdo_download(1.0, kHlt, 0x100C, 0, 100, 2);
  m.sdo_download(1.0, kHlt, 0x100D, 0, 3, 1);
  m.at(1.1, CanFrame::remote_frame(0x700 + kHlt, 1));  // one guarding request arms life guarding
  const Verdict v = run_master(m, 2);
  ASSERT_EQ(v.count(MasterRule::GuardingTimeout), 1u) << v.all();
  EXPECT_NE(v.first(MasterRule::GuardingTimeout)->text.find("guard time 100Ch = 100 ms, life time factor 100Dh = 3"),
            std::string::npos)
      << v.all();
}

TEST(MasterMonitor, SyncAgainstTheCommunicationCyclePeriod) {
  TestMaster m;
  m.sdo_download(1.0, kPump, 0x1006, 0, 10000);  // 10 ms
  for (double t : {1.10, 1.11, 1.12, 1.135, 1.145})
    m.at(t, CanFrame::data_frame(0x080, {}));
  const Verdict v = run_master(m, 1.5);
  ASSERT_EQ(v.count(MasterRule::SyncJitter), 1u) << v.all();
  EXPECT_NE(v.first(MasterRule::SyncJitter)->text.find("SYNC 15.000 ms after the previous one; node 63's communication cycle "
                                                       "period (1006h) is 10.000 ms"),
            std::string::npos)
      << v.all();
}

TEST(MasterMonitor, ACarefulMasterGetsNoFindings) {
  TestMaster m;
  // Waits for the boot-ups, configures PDOs the CiA 301 way, starts, sends SYNC on 1006h.
  m.sdo_upload(1.0, kDsv, 0x1000, 0);
  m.sdo_download(1.0, kPump, 0x1006, 0, 10000);
  m.sdo_download(1.0, kPump, 0x1801, 1, 0x800002BF);
  m.sdo_download(1.01, kPump, 0x1A01, 0, 0, 1);
  m.nmt(1.05, 0x01, 0);
  for (int i = 0; i < 50; ++i) m.at(1.1 + 0.01 * i, CanFrame::data_frame(0x080, {}));
  m.at(1.1, CanFrame::data_frame(0x200 + kDsv, {0x07, 0x00, 0x00, 0x00}));
  const Verdict v = run_master(m, 1.6);
  EXPECT_TRUE(v.findings.empty()) << v.all();
  EXPECT_NE(v.report.find("\"findings\": [], \"next\": 0, \"total\": 0, \"dropped\": 0"), std::string::npos) << v.report;
  EXPECT_EQ(v.junit.find("<failure"), std::string::npos) << v.junit;
}

TEST(MasterMonitor, ReferencePlantScriptedMasterGetsNoFindings) {
  scenario::RunOptions options;
  std::FILE* out = std::tmpfile();
  options.out = out;
  options.quiet = true;
  const auto s = scenario::load_scenario_file(VPLANT_SOURCE_DIR "/scenarios/reference-plant.yaml");
  scenario::Runner runner(s, vtest::test_environment(), options);
  EXPECT_EQ(runner.run(), 0);
  std::fclose(out);
  const auto& log = runner.master_monitor().findings();
  std::string texts;
  for (std::size_t i = 0; i < log.size(); ++i) texts += std::string(log[i].text.data()) + "\n";
  EXPECT_EQ(log.size(), 0u) << texts;
}

TEST(MasterMonitor, ReportJunitAndSummary) {
  TestMaster m;
  m.sdo_download(1.0, kDsv, 0x1000, 0, 1);  // sdo-abort: a warning
  m.sdo_upload(1.0, 9, 0x1000, 0);          // sdo-no-answer: an error
  const Verdict v = run_master(m, 2.5);
  EXPECT_NE(v.report.find("{\"rule\": \"sdo-abort\", \"severity\": \"warning\", \"t_us\": 100"), std::string::npos) << v.report;
  EXPECT_NE(v.report.find("\"bus\": \"main\", \"node\": 2, \"text\": \"node 2 aborted the master's SDO download of 1000h:00"),
            std::string::npos)
      << v.report;
  EXPECT_NE(v.report.find("\"from\": \"master\", \"frame\": \"602#2300100001000000\"}, "), std::string::npos) << v.report;
  EXPECT_NE(v.report.find("\"from\": \"node\", \"frame\": \"582#8000100000000106\"}]"), std::string::npos) << v.report;
  EXPECT_NE(v.report.find("\"sdo-no-answer\": {\"severity\": \"error\", \"count\": 1}"), std::string::npos) << v.report;
  // One test case per rule; only the error rule with findings fails.
  EXPECT_NE(v.junit.find("master rule sync-jitter"), std::string::npos) << v.junit;
  EXPECT_NE(v.junit.find("master rule sdo-abort"), std::string::npos) << v.junit;
  std::size_t failures = 0;
  for (auto at = v.junit.find("<failure"); at != std::string::npos; at = v.junit.find("<failure", at + 1)) ++failures;
  EXPECT_EQ(failures, 1u) << v.junit;
  EXPECT_NE(v.output.find("master findings: 2 (1 errors, 1 warnings)"), std::string::npos) << v.output;
  EXPECT_NE(v.output.find("sdo-no-answer (error) at 2.0"), std::string::npos) << v.output;
}

TEST(MasterMonitor, ScenarioSetsSeverities) {
  TestMaster m;
  m.sdo_download(1.0, kDsv, 0x1000, 0, 1);
  m.sdo_upload(1.0, 9, 0x1000, 0);
  const Verdict v = run_master(m, 2.5, "master_rules: {sdo-abort: error, sdo-no-answer: off}\n");
  ASSERT_EQ(v.findings.size(), 1u) << v.all();
  EXPECT_NE(v.report.find("\"rule\": \"sdo-abort\", \"severity\": \"error\""), std::string::npos) << v.report;
  EXPECT_EQ(v.junit.find("master rule sdo-no-answer"), std::string::npos) << v.junit;
}

TEST(MasterMonitor, ScenarioKeyIsValidated) {
  const auto error_of = [](const std::string& rules) {
    try {
      scenario::parse_scenario(kNodes + rules, "rules.yaml", ".");
    } catch (const scenario::LoadError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error_of("master_rules: {sdo-abrt: off}\n").find("rules.yaml:8:16: unknown master rule 'sdo-abrt' (rules: before-boot-up, "),
            std::string::npos)
      << error_of("master_rules: {sdo-abrt: off}\n");
  EXPECT_NE(error_of("master_rules: {sdo-abort: fatal}\n").find("rules.yaml:8:27: master_rules.sdo-abort: 'fatal' is not off, warning or error"),
            std::string::npos)
      << error_of("master_rules: {sdo-abort: fatal}\n");
  EXPECT_NE(error_of("master_rules: [sdo-abort]\n").find("rules.yaml:8:15: master_rules must be a mapping"), std::string::npos)
      << error_of("master_rules: [sdo-abort]\n");
}

TEST(FindingLog, BoundedWithACountOfDropped) {
  scenario::FindingLog log(2);
  for (int i = 0; i < 5; ++i) {
    log.count(MasterRule::SyncJitter);
    if (auto* f = log.claim()) {
      f->rule = MasterRule::SyncJitter;
      log.publish();
    }
  }
  EXPECT_EQ(log.size(), 2u);
  EXPECT_EQ(log.dropped(), 3u);
  EXPECT_EQ(log.count_of(MasterRule::SyncJitter), 5u);
}

}  // namespace
