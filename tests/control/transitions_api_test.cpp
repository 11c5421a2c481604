// GET /api/nodes/{name}/transitions and /machines against the reference plant in virtual time:
// every machine (NMT, DSP 408 of the DSV and of each MD2 channel, VT-VPCD, CiA 406 bits) and
// every cause the devices record (boot, control word, NMT command, input, heartbeat timeout,
// guarding timeout, bus-off, power, device fault), as the lessons need them.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <mutex>
#include <thread>

#include "engine/running/environment.h"
#include "engine/loading/scenario_loader.h"
#include "tests/control/live_plant.h"

namespace {

using nlohmann::json;
using vtest::LivePlant;

class TransitionsApi : public ::testing::Test {
 protected:
  void SetUp() override {
    plant_ = std::make_unique<LivePlant>(scenario::load_scenario_file(VPLANT_REFERENCE_PLANT), scenario::default_environment());
    p().run_ms(600);  // every node booted
  }
  LivePlant& p() { return *plant_; }
  json get(const std::string& path) { return LivePlant::json_of(p().http().Get(path.c_str())); }
  int status(const httplib::Result& r) { return r ? r->status : -1; }
  void sdo(const std::string& node, int index, int sub, std::int64_t value) {
    const auto r = LivePlant::json_of(p().post("/api/nodes/" + node + "/sdo", {{"index", index}, {"sub", sub}, {"value", value}}));
    ASSERT_EQ(r["ok"], true) << r.dump();
  }
  void nmt(const std::string& command, const json& node) {
    ASSERT_EQ(status(p().post("/api/nmt", {{"command", command}, {"node", node}})), 200);
  }
  /// The entries of `machine` after `after`.
  json of(const std::string& node, const std::string& machine, std::uint64_t after = 0) {
    json out = json::array();
    for (const auto& t : get("/api/nodes/" + node + "/transitions?after=" + std::to_string(after)))
      if (t["machine"] == machine) out.push_back(t);
    return out;
  }
  std::uint64_t last_seq(const std::string& node) {
    const auto all = get("/api/nodes/" + node + "/transitions");
    return all.empty() ? 0 : all.back()["seq"].get<std::uint64_t>();
  }
  static std::vector<std::string> names(const json& entries) {
    std::vector<std::string> out;
    for (const auto& t : entries) out.push_back(t["transition"]);
    return out;
  }
  json machine(const std::string& node, const std::string& name) {
    const auto all = get("/api/nodes/" + node + "/machines");
    for (const auto& m : all["machines"])
      if (m["machine"] == name) return m;
    ADD_FAILURE() << node << " has no machine " << name;
    return {};
  }

  std::unique_ptr<LivePlant> plant_;
};

TEST_F(TransitionsApi, BootIsRecordedOldestFirstWithEvidence) {
  const auto all = get("/api/nodes/dsv/transitions");
  ASSERT_GE(all.size(), 4u);
  for (std::size_t k = 1; k < all.size(); ++k) EXPECT_LT(all[k - 1]["seq"], all[k]["seq"]);
  const auto n = of("dsv", "nmt");
  ASSERT_GE(n.size(), 2u);
  EXPECT_EQ(n[0]["from"], "OFF");
  EXPECT_EQ(n[0]["to"], "INITIALISING");
  EXPECT_EQ(n[0]["cause"], "boot");
  EXPECT_EQ(n[1]["transition"], "boot-up");
  EXPECT_EQ(n[1]["to"], "PRE-OPERATIONAL");
  const auto d = of("dsv", "dsp408");
  ASSERT_GE(d.size(), 2u);
  EXPECT_EQ(names(d)[0], "TR_0");
  EXPECT_EQ(d[0]["from"], "OFF");
  EXPECT_EQ(d[1]["transition"], "TR_1");
  EXPECT_EQ(d[1]["to"], "INIT");
  for (const auto& t : all) {
    for (const char* key : {"seq", "t_us", "machine", "from", "to", "transition", "cause", "value", "detail", "evidence"})
      EXPECT_TRUE(t.contains(key)) << key << " in " << t.dump();
    EXPECT_FALSE(t["evidence"].get<std::string>().empty());
  }
  // ?after= gives only the newer ones; bad input is refused.
  const auto after = get("/api/nodes/dsv/transitions?after=" + all[1]["seq"].dump());
  ASSERT_EQ(after.size(), all.size() - 2);
  EXPECT_EQ(after[0]["seq"], all[2]["seq"]);
  EXPECT_EQ(status(p().http().Get("/api/nodes/dsv/transitions?after=-1")), 400);
  EXPECT_EQ(status(p().http().Get("/api/nodes/dsv/transitions?after=x")), 400);
  EXPECT_EQ(status(p().http().Get("/api/nodes/ghost/transitions")), 404);
  EXPECT_EQ(status(p().http().Get("/api/nodes/ghost/machines")), 404);
}

// The "Done when": each step of a control word write on its own, with the word as cause.
TEST_F(TransitionsApi, ControlWordsGiveEachTransitionWithTheWordAsCause) {
  nmt("start", 0);
  p().run_ms(5);
  const auto seq = last_seq("dsv");
  for (int cw : {0x0001, 0x0003, 0x0007}) {
    sdo("dsv", 0x6040, 0, cw);
    p().run_ms(2);
  }
  auto up = of("dsv", "dsp408", seq);
  ASSERT_EQ(names(up), (std::vector<std::string>{"TR_2", "TR_3", "TR_4"})) << up.dump();
  EXPECT_EQ(up[2]["to"], "DEVICE_MODE_ACTIVE");
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(up[k]["cause"], "control_word");
    EXPECT_EQ(up[k]["value"], (k == 0 ? 1 : k == 1 ? 3 : 7));
    EXPECT_EQ(up[k]["detail"], "SDO");
  }
  EXPECT_EQ(up[2]["evidence"], "control word 0x0007 (D=1 H=1 M=1 R=0) by SDO");
  EXPECT_EQ(machine("dsv", "dsp408")["state"], "DEVICE_MODE_ACTIVE");

  const auto active = last_seq("dsv");
  sdo("dsv", 0x6040, 0, 0x0000);
  p().run_ms(2);
  const auto down = of("dsv", "dsp408", active);
  ASSERT_EQ(names(down), (std::vector<std::string>{"TR_5", "TR_6", "TR_7"})) << down.dump();
  for (const auto& t : down) {
    EXPECT_EQ(t["cause"], "control_word");
    EXPECT_EQ(t["value"], 0);
    EXPECT_EQ(t["evidence"], "control word 0x0000 (D=0 H=0 M=0 R=0) by SDO");
  }
  EXPECT_EQ(down[2]["to"], "INIT");
}

TEST_F(TransitionsApi, NmtStopInActiveIsTr8CausedByTheCommand) {
  nmt("start", 0);
  p().run_ms(5);
  sdo("dsv", 0x6040, 0, 0x0007);
  p().run_ms(2);
  const auto seq = last_seq("dsv");
  nmt("stop", "dsv");
  p().run_ms(5);
  const auto n = of("dsv", "nmt", seq);
  ASSERT_EQ(n.size(), 1u) << n.dump();
  EXPECT_EQ(n[0]["transition"], "NMT 02h");
  EXPECT_EQ(n[0]["to"], "STOPPED");
  EXPECT_EQ(n[0]["cause"], "nmt_command");
  EXPECT_EQ(n[0]["value"], 2);
  EXPECT_EQ(n[0]["evidence"], "NMT Stop Remote Node (02h) from the master");
  const auto d = of("dsv", "dsp408", seq);
  ASSERT_EQ(names(d), (std::vector<std::string>{"TR_8", "TR_12"})) << d.dump();
  EXPECT_EQ(d[0]["from"], "DEVICE_MODE_ACTIVE");
  EXPECT_EQ(d[1]["to"], "FAULT");
  for (const auto& t : d) {
    EXPECT_EQ(t["cause"], "nmt_command") << t.dump();
    EXPECT_EQ(t["value"], 2);
  }
}

TEST_F(TransitionsApi, ResetCommunicationAndResetNodeAreListedWithTheirCause) {
  nmt("start", 0);
  p().run_ms(5);
  sdo("dsv", 0x6040, 0, 0x0007);
  p().run_ms(2);
  auto seq = last_seq("dsv");
  nmt("reset_communication", "dsv");
  p().run_ms(50);
  auto n = of("dsv", "nmt", seq);
  ASSERT_EQ(n.size(), 2u) << n.dump();
  EXPECT_EQ(n[0]["transition"], "NMT 82h");
  EXPECT_EQ(n[0]["from"], "OPERATIONAL");
  EXPECT_EQ(n[0]["to"], "INITIALISING");
  EXPECT_EQ(n[0]["evidence"], "NMT Reset Communication (82h) from the master");
  EXPECT_EQ(n[1]["transition"], "boot-up");
  EXPECT_EQ(n[1]["cause"], "nmt_command");  // the boot-up that the reset started
  // The forced TR_8 (C12-C14), after the boot-up, names the reset.
  auto d = of("dsv", "dsp408", seq);
  ASSERT_FALSE(d.empty());
  EXPECT_EQ(d[0]["transition"], "TR_8");
  EXPECT_EQ(d[0]["value"], 0x82);

  // Reset Node from ACTIVE: TR_567 forced, then the application reset.
  sdo("dsv", 0x6040, 0, 0x0008);  // R edge: back to DISABLED
  sdo("dsv", 0x6040, 0, 0x0007);
  p().run_ms(2);
  ASSERT_EQ(machine("dsv", "dsp408")["state"], "DEVICE_MODE_ACTIVE");
  seq = last_seq("dsv");
  nmt("reset_node", "dsv");
  p().run_ms(50);
  d = of("dsv", "dsp408", seq);
  ASSERT_FALSE(d.empty());
  EXPECT_EQ(d[0]["transition"], "TR_567");
  EXPECT_EQ(d[0]["from"], "DEVICE_MODE_ACTIVE");
  EXPECT_EQ(d[0]["value"], 0x81);
  n = of("dsv", "nmt", seq);
  ASSERT_FALSE(n.empty());
  EXPECT_EQ(n[0]["transition"], "NMT 81h");
}

TEST_F(TransitionsApi, EnableInputForcesTr567) {
  nmt("start", 0);
  p().run_ms(5);
  sdo("dsv", 0x6040, 0, 0x0007);
  p().run_ms(2);
  const auto seq = last_seq("dsv");
  ASSERT_EQ(status(p().post("/api/nodes/dsv/inputs", {{"name", "enable_input"}, {"value", 0}})), 200);
  p().run_ms(5);
  const auto d = of("dsv", "dsp408", seq);
  ASSERT_EQ(d.size(), 1u) << d.dump();
  EXPECT_EQ(d[0]["transition"], "TR_567");
  EXPECT_EQ(d[0]["cause"], "input");
  EXPECT_EQ(d[0]["detail"], "enable input");
  EXPECT_EQ(d[0]["value"], 0);
}

TEST_F(TransitionsApi, Md2ChannelsHaveAMachineEach) {
  nmt("start", 0);
  p().run_ms(5);
  const auto m = get("/api/nodes/md2/machines");
  std::vector<std::string> machines;
  for (const auto& x : m["machines"]) machines.push_back(x["machine"]);
  ASSERT_GE(machines.size(), 3u);
  EXPECT_EQ(machines[0], "nmt");
  EXPECT_EQ(machines[1], "dsp408.ch1");
  EXPECT_EQ(machines[2], "dsp408.ch2");
  const auto seq = last_seq("md2");
  sdo("md2", 0x6840, 0, 0x0007);  // channel 2's control word
  p().run_ms(2);
  EXPECT_TRUE(of("md2", "dsp408.ch1", seq).empty());
  EXPECT_EQ(names(of("md2", "dsp408.ch2", seq)), (std::vector<std::string>{"TR_2", "TR_3", "TR_4"}));
  EXPECT_EQ(machine("md2", "dsp408.ch2")["state"], "DEVICE_MODE_ACTIVE");
}

// The WDGA consumes the DSV's heartbeat; when it stops, the drop to PRE-OPERATIONAL is the
// timeout's doing (1029h:01), not an NMT 80h.
TEST_F(TransitionsApi, HeartbeatConsumerTimeoutIsTheCauseNotNmt80h) {
  nmt("start", 0);
  sdo("dsv", 0x1017, 0, 50);
  sdo("wdga", 0x1016, 1, (2 << 16) | 200);
  p().run_ms(300);
  ASSERT_EQ(machine("wdga", "nmt")["state"], "OPERATIONAL");
  const auto seq = last_seq("wdga");
  sdo("dsv", 0x1017, 0, 0);
  p().run_ms(400);
  const auto n = of("wdga", "nmt", seq);
  ASSERT_EQ(n.size(), 1u) << n.dump();
  EXPECT_EQ(n[0]["to"], "PRE-OPERATIONAL");
  EXPECT_EQ(n[0]["cause"], "heartbeat_timeout");
  EXPECT_EQ(n[0]["transition"], "1029h:01");
  EXPECT_EQ(n[0]["value"], 2);
  EXPECT_EQ(n[0]["evidence"], "heartbeat of node 2 missed (1016h consumer)");
}

TEST_F(TransitionsApi, LifeGuardingTimeoutForcesTr8) {
  nmt("start", 0);
  sdo("dsv", 0x6040, 0, 0x0007);
  sdo("dsv", 0x100C, 0, 20);
  sdo("dsv", 0x100D, 0, 2);
  ASSERT_EQ(status(p().post("/api/frames", {{"bus", "main"}, {"id", 0x702}, {"rtr", true}, {"dlc", 1}})), 200);
  p().run_ms(5);
  const auto seq = last_seq("dsv");
  p().run_ms(100);
  const auto d = of("dsv", "dsp408", seq);
  ASSERT_FALSE(d.empty());
  EXPECT_EQ(d[0]["transition"], "TR_8");
  EXPECT_EQ(d[0]["cause"], "guarding_timeout");
  EXPECT_EQ(d[0]["value"], 40);
}

TEST_F(TransitionsApi, PowerOffShowsOffAndPowerOnBootsAgain) {
  nmt("start", 0);
  sdo("dsv", 0x6040, 0, 0x0007);
  p().run_ms(2);
  const auto seq = last_seq("dsv");
  const auto r = LivePlant::json_of(p().post("/api/faults", {{"power_off", "dsv"}}));
  ASSERT_EQ(r["active"], true);
  p().run_ms(5);
  auto m = get("/api/nodes/dsv/machines");
  EXPECT_EQ(m["powered"], false);
  for (const auto& x : m["machines"]) EXPECT_EQ(x["state"], "OFF") << x["machine"];
  EXPECT_EQ(get("/api/nodes/dsv")["device"]["state"], "OFF");  // no DEVICE_MODE_ACTIVE while unpowered
  auto n = of("dsv", "nmt", seq);
  ASSERT_EQ(n.size(), 1u);
  EXPECT_EQ(n[0]["to"], "OFF");
  EXPECT_EQ(n[0]["cause"], "power");
  auto d = of("dsv", "dsp408", seq);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0]["from"], "DEVICE_MODE_ACTIVE");
  EXPECT_EQ(d[0]["to"], "OFF");
  ASSERT_EQ(status(p().http().Delete(("/api/faults/" + std::to_string(r["id"].get<int>())).c_str())), 200);
  p().run_ms(600);
  n = of("dsv", "nmt", seq);
  ASSERT_EQ(n.size(), 3u) << n.dump();
  EXPECT_EQ(n[1]["from"], "OFF");
  EXPECT_EQ(n[1]["cause"], "power");
  EXPECT_EQ(n[2]["to"], "PRE-OPERATIONAL");
  d = of("dsv", "dsp408", seq);
  ASSERT_EQ(names(d), (std::vector<std::string>{"", "TR_0", "TR_1"}));
  EXPECT_EQ(machine("dsv", "dsp408")["state"], "INIT");
  EXPECT_TRUE(get("/api/nodes/dsv/machines")["powered"]);
}

// Issue 21: a live power_off is over once its node has power again by any path (power_on, reset,
// a power cycle's end); it leaves GET /api/faults, and deleting it (or its `for:` running out)
// does not boot the node a second time. The node view says OFF only while unpowered.
TEST_F(TransitionsApi, PowerOffFaultIsOverOnceTheNodeHasPowerAgain) {
  const auto listed_node = [&](const std::string& name) {
    for (const auto& n : get("/api/nodes"))
      if (n["name"] == name) return n;
    ADD_FAILURE() << "no node " << name;
    return json{};
  };
  const auto boots = [&](std::uint64_t after) {
    std::size_t k = 0;
    for (const auto& t : of("wdga", "nmt", after)) k += t["from"] == "OFF" ? 1u : 0u;
    return k;
  };
  for (const json& again : {json{{"power_on", "wdga"}}, json{{"reset", "wdga"}}, json{{"power_cycle", {{"node", "wdga"}, {"off", "10ms"}}}}}) {
    const auto seq = last_seq("wdga");
    const auto off = LivePlant::json_of(p().post("/api/faults", {{"power_off", "wdga"}, {"for", "300ms"}}));
    ASSERT_EQ(off["active"], true) << off.dump();
    p().run_ms(5);
    ASSERT_EQ(get("/api/faults").size(), 1u);
    EXPECT_EQ(listed_node("wdga")["nmt"], "OFF");
    EXPECT_EQ(get("/api/nodes/wdga/machines")["powered"], false);
    const auto on = p().post("/api/faults", again);
    ASSERT_EQ(status(on), 200) << again.dump();
    p().run_ms(20);
    EXPECT_TRUE(get("/api/faults").empty()) << again.dump() << " left " << get("/api/faults").dump();
    EXPECT_NE(listed_node("wdga")["nmt"], "OFF") << again.dump();
    EXPECT_EQ(get("/api/nodes/wdga/machines")["powered"], true);
    const json machines = get("/api/nodes/wdga/machines");  // the range below must not outlive it
    for (const auto& m : machines["machines"]) EXPECT_NE(m["state"], "OFF") << m["machine"];
    // The stale fault: deleting it is a 404 and changes nothing; nor does its `for:` running out.
    EXPECT_EQ(status(p().http().Delete(("/api/faults/" + std::to_string(off["id"].get<int>())).c_str())), 404);
    p().run_ms(600);
    EXPECT_EQ(boots(seq), 1u) << again.dump() << " " << of("wdga", "nmt", seq).dump();
    EXPECT_NE(listed_node("wdga")["nmt"], "OFF");  // powered (it waits for a frame to detect the bit rate)
  }
  // Cleared while still off: powers the node on once.
  const auto seq = last_seq("wdga");
  const auto off = LivePlant::json_of(p().post("/api/faults", {{"power_off", "wdga"}}));
  p().run_ms(5);
  ASSERT_EQ(status(p().http().Delete(("/api/faults/" + std::to_string(off["id"].get<int>())).c_str())), 200);
  p().run_ms(600);
  EXPECT_EQ(boots(seq), 1u);
  EXPECT_TRUE(get("/api/faults").empty());
}

TEST_F(TransitionsApi, VtvpcdStatesIncludingTheLatchedFaultAndItsAcknowledgement) {
  auto v = of("vtvpcd", "vtvpcd");
  ASSERT_EQ(v.size(), 2u) << v.dump();
  EXPECT_EQ(v[0]["to"], "INITIALISING");
  EXPECT_EQ(v[1]["from"], "INITIALISING");
  EXPECT_EQ(v[1]["transition"], "boot-up");
  EXPECT_EQ(v[1]["to"], "RUNNING");
  const auto m = machine("vtvpcd", "vtvpcd");
  EXPECT_EQ(m["state"], "RUNNING");
  EXPECT_NE(m["note"].get<std::string>().find("1 → 0 → 1"), std::string::npos);

  // A stop fault, then its cause removed: still latched until the enable edge.
  const auto seq = last_seq("vtvpcd");
  const auto r = LivePlant::json_of(p().post("/api/faults", {{"device_fault", {{"node", "vtvpcd"}, {"fault", "lvdt_fault"}}}}));
  ASSERT_EQ(r["ok"], true) << r.dump();
  p().run_ms(10);
  ASSERT_EQ(status(p().http().Delete(("/api/faults/" + std::to_string(r["id"].get<int>())).c_str())), 200);
  p().run_ms(10);
  EXPECT_EQ(machine("vtvpcd", "vtvpcd")["state"], "FAULT_STOP");
  ASSERT_EQ(status(p().post("/api/nodes/vtvpcd/inputs", {{"name", "enable"}, {"value", 0}})), 200);
  p().run_ms(10);
  ASSERT_EQ(status(p().post("/api/nodes/vtvpcd/inputs", {{"name", "enable"}, {"value", 1}})), 200);
  p().run_ms(10);
  v = of("vtvpcd", "vtvpcd", seq);
  ASSERT_EQ(names(v), (std::vector<std::string>{"stop fault", "acknowledge"})) << v.dump();
  EXPECT_EQ(v[0]["cause"], "device_fault");
  EXPECT_NE(v[0]["value"], 0);  // its EMCY code
  EXPECT_EQ(v[1]["cause"], "input");
  EXPECT_EQ(v[1]["to"], "RUNNING");
}

TEST_F(TransitionsApi, VtvpcdIsInitialisingUntilItsBootUp) {
  const auto r = LivePlant::json_of(p().post("/api/faults", {{"reset", "vtvpcd"}}));
  p().run_ms(1);
  EXPECT_EQ(machine("vtvpcd", "vtvpcd")["state"], "INITIALISING");
  EXPECT_NE(get("/api/nodes/vtvpcd")["device"]["state"], "RUNNING");
  p().run_ms(600);
  EXPECT_EQ(machine("vtvpcd", "vtvpcd")["state"], "RUNNING");
}

TEST_F(TransitionsApi, Cia406BitsAreNamedMachines) {
  nmt("start", 0);
  p().run_ms(5);
  const auto alarms = machine("hlt", "cia406.alarms");
  EXPECT_EQ(alarms["state"], "none");
  bool named = false;
  for (const auto& s : alarms["states"]) named |= s["name"] == "position error" && s["kind"] == "fault";
  EXPECT_TRUE(named) << alarms.dump();
  EXPECT_FALSE(machine("hlt", "cia406.status").empty());
  EXPECT_FALSE(machine("wdga", "cia406.warnings")["states"].empty());
  const auto seq = last_seq("hlt");
  const auto r = LivePlant::json_of(p().post("/api/faults", {{"device_fault", {{"node", "hlt"}, {"fault", "magnet_lost"}}}}));
  p().run_ms(20);
  EXPECT_EQ(machine("hlt", "cia406.alarms")["state"], "position error");
  ASSERT_EQ(status(p().http().Delete(("/api/faults/" + std::to_string(r["id"].get<int>())).c_str())), 200);
  p().run_ms(20);
  const auto a = of("hlt", "cia406.alarms", seq);
  ASSERT_EQ(a.size(), 2u) << a.dump();
  EXPECT_EQ(a[0]["from"], "none");
  EXPECT_EQ(a[0]["to"], "position error");
  EXPECT_EQ(a[0]["transition"], "set");
  // Raised by the device fault: its EMCY code (the HLT 1100's position error, FF00h) is the evidence.
  EXPECT_EQ(a[0]["cause"], "device_fault");
  EXPECT_EQ(a[0]["value"], 0xFF00);
  EXPECT_EQ(a[0]["evidence"], "device fault position error (EMCY FF00h)");
  EXPECT_EQ(a[1]["to"], "none");
  EXPECT_EQ(a[1]["evidence"], "Alarms 6503h (CiA 406) = 0x0000");
}

TEST_F(TransitionsApi, MachinesDescribeStatesAndEdges) {
  const auto m = get("/api/nodes/dsv/machines");
  EXPECT_EQ(m["node"], "dsv");
  EXPECT_EQ(m["powered"], true);
  const auto d = machine("dsv", "dsp408");
  std::vector<std::string> edges;
  for (const auto& e : d["edges"]) {
    edges.push_back(e["transition"]);
    EXPECT_FALSE(e["condition"].get<std::string>().empty());
  }
  for (const char* tr : {"TR_0", "TR_1", "TR_2", "TR_3", "TR_4", "TR_5", "TR_6", "TR_7", "TR_8", "TR_9", "TR_10", "TR_11", "TR_12", "TR_567"})
    EXPECT_NE(std::find(edges.begin(), edges.end(), tr), edges.end()) << tr;
  for (const auto& s : d["states"]) {
    EXPECT_TRUE(s["row"].is_number());
    EXPECT_TRUE(s["col"].is_number());
  }
  const auto n = machine("dsv", "nmt");
  EXPECT_EQ(n["state"], "PRE-OPERATIONAL");
  EXPECT_EQ(n["states"].size(), 5u);
  EXPECT_FALSE(n["note"].get<std::string>().empty());
}

// The stream carries each transition as its own event, named by node.
TEST_F(TransitionsApi, StreamCarriesTransitionEvents) {
  nmt("start", 0);
  p().run_ms(5);
  std::string stream;
  std::mutex mu;
  std::atomic<bool> stop{false};
  std::thread reader([&] {
    httplib::Client sse("127.0.0.1", p().port());
    sse.set_read_timeout(5, 0);
    sse.Get("/api/events", [&](const char* data, std::size_t n) {
      std::lock_guard lk(mu);
      stream.append(data, n);
      return !stop.load();
    });
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(150));
  sdo("dsv", 0x6040, 0, 0x0007);
  p().run_ms(5);
  bool seen = false;
  for (int i = 0; i < 100 && !seen; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    std::lock_guard lk(mu);
    seen = stream.find("\"TR_4\"") != std::string::npos;
  }
  stop = true;
  reader.join();
  ASSERT_TRUE(seen) << stream.substr(0, 2000);
  const auto at = stream.find("event: transition\ndata: ");
  ASSERT_NE(at, std::string::npos);
  const auto start = at + std::string("event: transition\ndata: ").size();
  const auto j = json::parse(stream.substr(start, stream.find('\n', start) - start));
  EXPECT_EQ(j["node"], "dsv");
  EXPECT_EQ(j["machine"], "dsp408");
  EXPECT_EQ(j["transition"], "TR_2");
  EXPECT_EQ(j["cause"], "control_word");
  EXPECT_FALSE(j["evidence"].get<std::string>().empty());
}

}  // namespace
