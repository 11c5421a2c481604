// The control plane's HTTP API against the reference plant in virtual time: every endpoint, the
// bad requests (4xx, nothing changed), the Host/Origin refusal, SDO writes over the bus seen in
// the decoded stream, fault injection and clearing, the clock.
#include <gtest/gtest.h>

#include <cstdio>

#include "engine/running/environment.h"
#include "engine/loading/scenario_loader.h"
#include "tests/control/live_plant.h"

namespace {

using nlohmann::json;
using vtest::LivePlant;

scenario::Scenario reference_plant() { return scenario::load_scenario_file(VPLANT_REFERENCE_PLANT); }

class ControlApi : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { plant_ = new LivePlant(reference_plant(), scenario::default_environment()); }
  static void TearDownTestSuite() {
    delete plant_;
    plant_ = nullptr;
  }
  LivePlant& p() { return *plant_; }
  json get(const std::string& path) { return LivePlant::json_of(p().http().Get(path.c_str())); }
  int status(const httplib::Result& r) { return r ? r->status : -1; }
  json node(const std::string& name) { return get("/api/nodes/" + name); }
  /// Nodes booted and started (idempotent: the suite shares one run).
  void start_all() {
    if (node("dsv")["nmt"] == "OPERATIONAL") return;
    p().run_ms(600);
    ASSERT_EQ(status(p().post("/api/nmt", {{"command", "start"}, {"node", 0}})), 200);
    p().run_ms(20);
    ASSERT_EQ(node("dsv")["nmt"], "OPERATIONAL");
  }

  static LivePlant* plant_;
};
LivePlant* ControlApi::plant_ = nullptr;

TEST_F(ControlApi, ScenarioListsBusesNodesSignalsFaultsAndInputs) {
  const auto s = get("/api/scenario");
  EXPECT_EQ(s["name"], "reference-plant");
  EXPECT_EQ(s["clock"]["mode"], "virtual");
  EXPECT_EQ(s["clock"]["tick_us"], 1000);
  ASSERT_EQ(s["buses"].size(), 1u);
  EXPECT_EQ(s["buses"][0]["name"], "main");
  ASSERT_EQ(s["nodes"].size(), 5u);
  std::map<std::string, std::string> profiles;
  for (const auto& n : s["nodes"]) profiles[n["name"]] = n["profile"];
  EXPECT_EQ(profiles["dsv"], "dsp408");
  EXPECT_EQ(profiles["md2"], "dsp408");
  EXPECT_EQ(profiles["vtvpcd"], "vtvpcd");
  EXPECT_EQ(profiles["hlt"], "cia406");
  EXPECT_EQ(profiles["wdga"], "cia406");
  // Signals carry their SI unit and the display unit their owner (the plant model, the device) chose.
  std::map<std::string, nlohmann::json> signals;
  for (const auto& sig : s["signals"]) signals[sig["name"]] = sig;
  ASSERT_TRUE(signals.count("cyl.position"));
  EXPECT_EQ(signals["cyl.position"]["unit"], "m");
  EXPECT_EQ(signals["cyl.position"]["display_unit"], "mm");
  EXPECT_DOUBLE_EQ(signals["cyl.position"]["display_scale"].get<double>(), 1000.0);
  EXPECT_DOUBLE_EQ(signals["cyl.position"]["display_offset"].get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(signals["cyl.position"]["display_span"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(signals["p_supply.pressure"]["display_span"].get<double>(), 1.0);
  for (const auto& [name, sig] : signals) {
    EXPECT_FALSE(sig["unit"].get<std::string>().empty()) << name;
    EXPECT_FALSE(sig["display_unit"].get<std::string>().empty()) << name;
    EXPECT_NE(sig["display_scale"].get<double>(), 0.0) << name;
    const std::map<std::string, std::string> expected{{"Pa", "bar"}, {"rad/s", "rpm"}, {"m^3/s", "l/min"}, {"m/s", "mm/s"}};
    const auto it = expected.find(sig["unit"].get<std::string>());
    if (it != expected.end()) {
      EXPECT_EQ(sig["display_unit"], it->second) << name;
    }
  }
  ASSERT_TRUE(signals.count("pump.pressure_b"));
  EXPECT_DOUBLE_EQ(signals["pump.pressure_b"]["display_scale"].get<double>(), 1e-5);
  ASSERT_TRUE(signals.count("dsv.solenoid_a_current"));
  EXPECT_EQ(signals["dsv.solenoid_a_current"]["display_unit"], "mA");
  bool magnet_lost = false;
  for (const auto& f : s["faults"]["device"]) magnet_lost |= f["node"] == "hlt" && f["name"] == "magnet_lost";
  EXPECT_TRUE(magnet_lost);
  EXPECT_FALSE(s["faults"]["plant"].empty());
  EXPECT_FALSE(s["inputs"].empty());
}

TEST_F(ControlApi, ClockStartsPausedStepsAndRuns) {
  auto c = get("/api/clock");
  EXPECT_EQ(c["mode"], "virtual");
  EXPECT_TRUE(c["paused"].get<bool>());
  const auto t0 = c["t_us"].get<std::int64_t>();
  // Paused: time stands.
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  EXPECT_EQ(get("/api/clock")["t_us"], t0);
  p().run_ms(1);  // step by "run 1 ms"
  ASSERT_EQ(status(p().post("/api/clock", {{"action", "step"}})), 200);
  for (int i = 0; i < 200 && get("/api/clock")["t_us"].get<std::int64_t>() < t0 + 2000; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  EXPECT_EQ(get("/api/clock")["t_us"], t0 + 2000);
  p().run_ms(50);
  EXPECT_EQ(get("/api/clock")["t_us"], t0 + 52000);
  // Resume (as fast as possible) and pause again: time moved on and stands again.
  ASSERT_EQ(status(p().post("/api/clock", {{"action", "resume"}, {"speed", 0}})), 200);
  std::this_thread::sleep_for(std::chrono::milliseconds(30));
  ASSERT_EQ(status(p().post("/api/clock", {{"action", "pause"}})), 200);
  std::this_thread::sleep_for(std::chrono::milliseconds(30));
  const auto t1 = get("/api/clock")["t_us"].get<std::int64_t>();
  EXPECT_GT(t1, t0 + 52000);
  std::this_thread::sleep_for(std::chrono::milliseconds(30));
  EXPECT_EQ(get("/api/clock")["t_us"], t1);
  // Bad clock requests.
  EXPECT_EQ(status(p().post("/api/clock", {{"action", "fly"}})), 400);
  EXPECT_EQ(status(p().post("/api/clock", {{"action", "run"}, {"ms", 0}})), 400);
  EXPECT_EQ(status(p().post("/api/clock", {{"action", "resume"}, {"speed", -1}})), 400);
  EXPECT_EQ(get("/api/clock")["paused"], true);
}

TEST_F(ControlApi, NodesShowNmtDeviceStateAndErrorRegister) {
  start_all();
  const auto nodes = get("/api/nodes");
  ASSERT_EQ(nodes.size(), 5u);
  for (const auto& n : nodes) EXPECT_EQ(n["nmt"], "OPERATIONAL") << n.dump();
  const auto dsv = node("dsv");
  EXPECT_EQ(dsv["node_id"], 2);
  EXPECT_EQ(dsv["bus"], "main");
  EXPECT_EQ(dsv["device"]["profile"], "dsp408");
  EXPECT_TRUE(dsv["device"].contains("status_word"));
  EXPECT_EQ(node("hlt")["device"]["profile"], "cia406");
  EXPECT_TRUE(node("vtvpcd")["device"]["faults"].is_array());
  EXPECT_EQ(status(p().http().Get("/api/nodes/nope")), 404);
}

TEST_F(ControlApi, Md2ShowsEveryChannelsStateMachine) {
  start_all();
  auto md2 = node("md2");
  ASSERT_TRUE(md2["device"]["channels"].is_array()) << md2.dump();
  const auto& channels = md2["device"]["channels"];
  ASSERT_GE(channels.size(), 2u);
  EXPECT_EQ(channels[0]["channel"], 1);
  EXPECT_EQ(channels[1]["channel"], 2);
  EXPECT_EQ(channels[0]["state"], md2["device"]["state"]);  // channel 1 is the device's own fields
  EXPECT_EQ(channels[0]["status_word"], md2["device"]["status_word"]);
  const auto ch1_cw = channels[0]["control_word"];
  // Channel 2's control word is 6040h + 800h: writing it moves channel 2 only.
  auto r = p().post("/api/nodes/md2/sdo", {{"index", 0x6840}, {"sub", 0}, {"value", 7}});
  ASSERT_EQ(status(r), 200) << (r ? r->body : "");
  ASSERT_EQ(LivePlant::json_of(r)["ok"], true) << r->body;
  p().run_ms(30);
  md2 = node("md2");
  const auto& after = md2["device"]["channels"];
  EXPECT_EQ(after[1]["control_word"], 7) << md2.dump();
  EXPECT_EQ(after[1]["state"], "DEVICE_MODE_ACTIVE") << md2.dump();
  ASSERT_TRUE(after[1]["last_transition"].is_object());
  EXPECT_EQ(after[1]["last_transition"]["control_word"], 7);
  EXPECT_EQ(after[0]["control_word"], ch1_cw);
  EXPECT_EQ(md2["device"]["control_word"], ch1_cw);
  // A single-channel valve has no channel list.
  EXPECT_FALSE(node("dsv")["device"].contains("channels"));
}

TEST_F(ControlApi, SdoWriteOfTheDsvControlWordDrivesTheStateMachineAndShowsInTheStream) {
  start_all();
  // A stream client first, so the frames of the write are captured.
  std::string stream;
  std::atomic<bool> stop{false};
  httplib::Client sse("127.0.0.1", p().port());
  sse.set_read_timeout(5, 0);
  std::thread reader([&] {
    sse.Get("/api/events?signals=cyl.position&rate=50", [&](const char* data, std::size_t n) {
      stream.append(data, n);
      return !stop.load();
    });
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(150));

  // A frame on the HLT 1100's TPDO1 (0x185): its position reads in mm (6005h:01 = 0.1 mm steps).
  ASSERT_EQ(status(p().post("/api/frames", {{"bus", "main"}, {"id", "0x185"}, {"data", "D2040000"}})), 200);
  auto r = p().post("/api/nodes/dsv/sdo", {{"index", 0x6040}, {"sub", 0}, {"value", 7}});
  ASSERT_EQ(status(r), 200) << (r ? r->body : "");
  EXPECT_EQ(LivePlant::json_of(r)["ok"], true);
  p().run_ms(30);
  const auto dsv = node("dsv");
  EXPECT_EQ(dsv["device"]["state"], "DEVICE_MODE_ACTIVE") << dsv.dump();
  EXPECT_EQ(dsv["device"]["control_word"], 7);
  ASSERT_TRUE(dsv["device"]["last_transition"].is_object());
  EXPECT_EQ(dsv["device"]["last_transition"]["to"], "DEVICE_MODE_ACTIVE");
  EXPECT_EQ(dsv["device"]["last_transition"]["control_word"], 7);

  for (int i = 0; i < 100 && stream.find("SDO download response 6040:00") == std::string::npos; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  stop = true;
  reader.join();
  EXPECT_NE(stream.find("event: nodes"), std::string::npos);
  EXPECT_NE(stream.find("event: clock"), std::string::npos);
  EXPECT_NE(stream.find("event: signals"), std::string::npos);
  EXPECT_NE(stream.find("\"cyl.position\""), std::string::npos);
  EXPECT_NE(stream.find("SDO download 6040:00 Device control word = 0x0007 (7)"), std::string::npos) << stream.substr(0, 2000);
  EXPECT_NE(stream.find("SDO download response 6040:00 Device control word: done"), std::string::npos);
  EXPECT_NE(stream.find("\"candump\":\"("), std::string::npos);  // candump -L lines
  EXPECT_NE(stream.find(" main 602#2B40600007000000"), std::string::npos);
  EXPECT_NE(stream.find("\"bytes\":\"2B 40 60 00 07 00 00 00\""), std::string::npos);  // spaced hex
  EXPECT_NE(stream.find("6020:01 Position value = 123.4 mm (raw 1234)"), std::string::npos)
      << stream.substr(stream.find("TPDO1 node 5") == std::string::npos ? 0 : stream.find("TPDO1 node 5"), 600);
}

TEST_F(ControlApi, SdoReadsAndRefusals) {
  start_all();
  auto r = LivePlant::json_of(p().post("/api/nodes/dsv/sdo/read", {{"index", "0x1000"}, {"sub", 0}}));
  EXPECT_EQ(r["ok"], true);
  EXPECT_EQ(r["data"].get<std::string>().size(), 8u);
  EXPECT_TRUE(r["value"].is_number());
  // The node refuses: the abort code and its text, answered 200 (the transfer itself worked). The
  // DSV answers a write to a read-only object with 0x06010000, as its manual lists.
  r = LivePlant::json_of(p().post("/api/nodes/dsv/sdo", {{"index", 0x1000}, {"sub", 0}, {"value", 1}}));
  EXPECT_EQ(r["ok"], false);
  EXPECT_EQ(r["abort_code"], "0x06010000");
  EXPECT_EQ(r["abort_text"], "unsupported access to an object");
  r = LivePlant::json_of(p().post("/api/nodes/dsv/sdo", {{"index", "0x6040"}, {"sub", 9}, {"data", "0700"}}));
  EXPECT_EQ(r["ok"], false);
  EXPECT_EQ(r["abort_code"], "0x06090011");
  // Refused here, nothing sent.
  EXPECT_EQ(status(p().post("/api/nodes/dsv/sdo", {{"index", 0x6040}, {"value", 70000}})), 400);   // UNSIGNED16 range
  EXPECT_EQ(status(p().post("/api/nodes/dsv/sdo", {{"index", 0x12345}, {"data", "00"}})), 400);    // index range
  EXPECT_EQ(status(p().post("/api/nodes/dsv/sdo", {{"index", 0x6040}, {"sub", 300}, {"value", 1}})), 400);
  EXPECT_EQ(status(p().post("/api/nodes/dsv/sdo", {{"index", 0x6040}})), 400);                      // no value
  EXPECT_EQ(status(p().post("/api/nodes/dsv/sdo", {{"index", 0x6040}, {"data", "0G"}})), 400);      // bad hex
  EXPECT_EQ(status(p().post("/api/nodes/dsv/sdo", {{"index", 0x5FFF}, {"value", 1}})), 400);        // unknown object
  EXPECT_EQ(status(p().post("/api/nodes/ghost/sdo", {{"index", 0x6040}, {"value", 1}})), 404);
  EXPECT_EQ(status(p().post("/api/nodes/dsv/sdo/read", json::object())), 400);
  EXPECT_EQ(status(p().post("/api/nodes/dsv/sdo/read", {{"index", "banana"}})), 400);
}

TEST_F(ControlApi, ObjectDictionaryListsEntriesWithValues) {
  const auto od = get("/api/nodes/dsv/od");
  ASSERT_TRUE(od.is_array());
  bool found = false;
  for (const auto& e : od) {
    if (e["index"] != 0x6040 || e["sub"] != 0) continue;
    found = true;
    EXPECT_EQ(e["type"], "UNSIGNED16");
    EXPECT_EQ(e["access"], "rw");
    EXPECT_TRUE(e["value"].is_number());
    EXPECT_FALSE(e["name"].get<std::string>().empty());
  }
  EXPECT_TRUE(found);
  EXPECT_EQ(status(p().http().Get("/api/nodes/ghost/od")), 404);
}

TEST_F(ControlApi, EntriesWithAProductScalingShowTheirUnitAndEngineeringValue) {
  const auto find = [](const nlohmann::json& od, int index, int sub) {
    for (const auto& e : od)
      if (e["index"] == index && e["sub"] == sub) return e;
    return nlohmann::json{};
  };
  // HLT 1100: position in steps of 0.1 mm (6005h:01 = 100000 nm).
  const auto hlt = get("/api/nodes/hlt/od");
  const auto position = find(hlt, 0x6020, 1);
  ASSERT_TRUE(position.is_object()) << "no 6020:01";
  EXPECT_EQ(position["unit"], "mm");
  char expected[32];
  std::snprintf(expected, sizeof expected, "%.1f mm", position["value"].get<double>() * 0.1);
  EXPECT_EQ(position["display"], expected);
  EXPECT_EQ(find(hlt, 0x6030, 1)["unit"], "mm/s");
  // WDGA multiturn: the position in turns of 6001h = 16384 steps.
  const auto wdga_position = find(get("/api/nodes/wdga/od"), 0x6004, 0);
  EXPECT_EQ(wdga_position["unit"], "turns");
  EXPECT_TRUE(wdga_position.contains("display"));
  // Entries the manual gives no scaling keep their raw value only.
  const auto cw = find(get("/api/nodes/dsv/od"), 0x6040, 0);
  EXPECT_FALSE(cw.contains("unit"));
  EXPECT_FALSE(cw.contains("display"));
}

TEST_F(ControlApi, NmtCommandsAndRawFrames) {
  start_all();
  ASSERT_EQ(status(p().post("/api/nmt", {{"command", "pre_operational"}, {"node", "wdga"}})), 200);
  p().run_ms(5);
  EXPECT_EQ(node("wdga")["nmt"], "PRE-OPERATIONAL");
  EXPECT_EQ(node("hlt")["nmt"], "OPERATIONAL");
  // A raw NMT start frame brings it back.
  ASSERT_EQ(status(p().post("/api/frames", {{"bus", "main"}, {"id", "0x000"}, {"data", "017F"}})), 200);
  p().run_ms(5);
  EXPECT_EQ(node("wdga")["nmt"], "OPERATIONAL");
  // reset_communication: back to pre-operational after its boot-up.
  ASSERT_EQ(status(p().post("/api/nmt", {{"command", "reset_communication"}, {"node", "wdga"}})), 200);
  p().run_ms(20);
  EXPECT_EQ(node("wdga")["nmt"], "PRE-OPERATIONAL");
  ASSERT_EQ(status(p().post("/api/nmt", {{"command", "start"}, {"node", "wdga"}})), 200);
  p().run_ms(5);
  EXPECT_EQ(node("wdga")["nmt"], "OPERATIONAL");
  EXPECT_EQ(status(p().post("/api/nmt", {{"command", "dance"}, {"node", 0}})), 400);
  // The old words are gone: one vocabulary.
  EXPECT_EQ(status(p().post("/api/nmt", {{"command", "preop"}, {"node", 0}})), 400);
  EXPECT_EQ(status(p().post("/api/nmt", {{"command", "reset_comm"}, {"node", 0}})), 400);
  EXPECT_EQ(status(p().post("/api/nmt", {{"command", "start"}, {"node", "ghost"}})), 404);
  EXPECT_EQ(status(p().post("/api/nmt", {{"command", "start"}, {"node", 5}})), 400);
  EXPECT_EQ(status(p().post("/api/frames", {{"id", 0x800}, {"data", "00"}})), 400);
  EXPECT_EQ(status(p().post("/api/frames", {{"id", 0x80}, {"data", "000102030405060708"}})), 400);
  EXPECT_EQ(status(p().post("/api/frames", {{"bus", "can9"}, {"id", 0x80}})), 404);
}

TEST_F(ControlApi, DeviceFaultInjectedAndClearedWithItsEmcy) {
  start_all();
  const auto before = node("hlt")["emcy"].size();
  auto r = LivePlant::json_of(p().post("/api/faults", {{"device_fault", {{"node", "hlt"}, {"fault", "magnet_lost"}}}}));
  ASSERT_EQ(r["ok"], true) << r.dump();
  EXPECT_EQ(r["active"], true);
  const int id = r["id"];
  p().run_ms(50);
  const auto hlt = node("hlt");
  ASSERT_GT(hlt["emcy"].size(), before) << hlt.dump();
  EXPECT_NE(hlt["error_register"], 0);
  EXPECT_NE(hlt["device"]["alarms"], 0);
  auto active = get("/api/faults");
  ASSERT_EQ(active.size(), 1u);
  EXPECT_EQ(active[0]["id"], id);
  EXPECT_NE(active[0]["summary"].get<std::string>().find("magnet_lost"), std::string::npos);
  ASSERT_EQ(status(p().http().Delete(("/api/faults/" + std::to_string(id)).c_str())), 200);
  p().run_ms(50);
  EXPECT_TRUE(get("/api/faults").empty());
  EXPECT_EQ(node("hlt")["device"]["alarms"], 0);
  EXPECT_EQ(status(p().http().Delete(("/api/faults/" + std::to_string(id)).c_str())), 404);
  EXPECT_EQ(status(p().http().Delete("/api/faults/abc")), 400);
}

TEST_F(ControlApi, EveryFaultKind) {
  start_all();
  const auto inject = [&](const json& body) {
    auto r = p().post("/api/faults", body);
    EXPECT_EQ(status(r), 200) << body.dump() << " → " << (r ? r->body : "");
    return r ? LivePlant::json_of(r) : json{};
  };
  // The scenario's fault actions as JSON (engine/loading/fault_codec.h): drop the HLT's TPDO2; bus-off;
  // power off; a plant parameter. Each one cleared.
  for (const auto& body : {json{{"drop", {{"bus", "main"}, {"id", "0x285"}}}},
                           json{{"bus_off", "md2"}},
                           json{{"power_off", "wdga"}},
                           json{{"plant", {{"parameter", "cyl.viscous_friction"}, {"value", 3000.0}}}}}) {
    const auto r = inject(body);
    ASSERT_EQ(r["active"], true) << body.dump();
    p().run_ms(5);
    ASSERT_EQ(status(p().http().Delete(("/api/faults/" + std::to_string(r["id"].get<int>())).c_str())), 200);
  }
  p().run_ms(5);
  EXPECT_TRUE(get("/api/faults").empty());
  // Power reset: nothing to clear.
  EXPECT_EQ(inject({{"reset", "wdga"}})["active"], false);
  // With `for:`: listed until it ends, then gone (the fault injector ended it).
  const auto timed = inject({{"tx_errors", {{"node", "dsv"}, {"count", 3}}}, {"for", "20ms"}});
  ASSERT_EQ(timed["active"], true);
  auto listed = get("/api/faults");
  ASSERT_EQ(listed.size(), 1u);
  EXPECT_EQ(listed[0]["id"], timed["id"]);
  EXPECT_EQ(listed[0]["until_t_us"].get<std::int64_t>() - listed[0]["since_t_us"].get<std::int64_t>(), 20000);
  p().run_ms(25);
  EXPECT_TRUE(get("/api/faults").empty());
  EXPECT_EQ(status(p().http().Delete(("/api/faults/" + std::to_string(timed["id"].get<int>())).c_str())), 404);
  // Refusals: nothing applied, the reason as `<body>:line:col: reason`.
  const auto refused = p().post("/api/faults", {{"device_fault", {{"node", "hlt"}, {"fault", "gremlins"}}}});
  EXPECT_EQ(status(refused), 400);
  EXPECT_EQ(LivePlant::json_of(refused)["error"].get<std::string>().rfind("<body>:1:1: fault: node 'hlt'", 0), 0u)
      << refused->body;
  EXPECT_EQ(status(p().post("/api/faults", {{"device_fault", {{"node", "ghost"}, {"fault", "magnet_lost"}}}})), 400);
  EXPECT_EQ(status(p().post("/api/faults", {{"plant", {{"parameter", "cyl.nonsense"}, {"value", 1}}}})), 400);
  EXPECT_EQ(status(p().post("/api/faults", {{"plant", {{"parameter", "cyl.viscous_friction"}, {"value", -5}}}})), 400);
  EXPECT_EQ(status(p().post("/api/faults", {{"melt", {{"id", "0x181"}}}})), 400);
  EXPECT_EQ(status(p().post("/api/faults", {{"kind", "device"}, {"node", "hlt"}, {"fault", "magnet_lost"}})), 400);
  EXPECT_EQ(status(p().http().Post("/api/faults", "{\"drop\": [", "application/json")), 400);
  EXPECT_TRUE(get("/api/faults").empty());
}

TEST_F(ControlApi, InputsAndSignals) {
  const auto s = get("/api/scenario");
  ASSERT_FALSE(s["inputs"].empty());
  const auto& in = s["inputs"][0];
  EXPECT_EQ(status(p().post("/api/nodes/" + in["node"].get<std::string>() + "/inputs", {{"name", in["name"]}, {"value", 0.5}})), 200);
  EXPECT_EQ(status(p().post("/api/nodes/dsv/inputs", {{"name", "warp_drive"}, {"value", 1}})), 400);
  EXPECT_EQ(status(p().post("/api/nodes/dsv/inputs", {{"name", "enable"}, {"value", "on"}})), 400);
  const auto v = get("/api/signals?names=cyl.position,pump.swivel_angle");
  EXPECT_TRUE(v["values"]["cyl.position"].is_number());
  EXPECT_TRUE(v["values"]["pump.swivel_angle"].is_number());
  ASSERT_EQ(v["signals"].size(), 2u);  // values stay SI; the metadata says how to show them
  EXPECT_EQ(v["signals"][1]["name"], "pump.swivel_angle");
  EXPECT_EQ(v["signals"][1]["unit"], "1");
  EXPECT_EQ(v["signals"][1]["display_unit"], "%");
  EXPECT_EQ(v["t_us"], get("/api/clock")["t_us"]);
  EXPECT_EQ(status(p().http().Get("/api/signals?names=cyl.warp")), 400);
  EXPECT_EQ(status(p().http().Get("/api/events?signals=cyl.warp")), 400);
  EXPECT_EQ(status(p().http().Get("/api/events?rate=500")), 400);
}

TEST_F(ControlApi, BadRequestsGet4xxWithAReason) {
  auto r = p().http().Post("/api/nmt", "{not json", "application/json");
  EXPECT_EQ(status(r), 400);
  EXPECT_NE(r->body.find("malformed JSON"), std::string::npos);
  EXPECT_EQ(status(p().http().Post("/api/nmt", "[1,2]", "application/json")), 400);
  r = p().http().Get("/api/nonsense");
  EXPECT_EQ(status(r), 404);
  EXPECT_NE(LivePlant::json_of(r)["error"].get<std::string>().find("no such endpoint"), std::string::npos);
  EXPECT_EQ(status(p().http().Put("/api/nmt", "{}", "application/json")), 405);
  EXPECT_EQ(status(p().http().Delete("/api/nodes")), 405);
  EXPECT_EQ(status(p().http().Post("/api/nodes/dsv/od", "{}", "application/json")), 405);
  const std::string huge(200 * 1024, ' ');
  EXPECT_EQ(status(p().http().Post("/api/nmt", huge, "application/json")), 413);
}

// A body is read as strictly as a scenario file: a misspelt optional key is refused with its place,
// not ignored (here `subindex` would have read object 1018:00 instead of 1018:01).
TEST_F(ControlApi, BodiesAreReadLikeAScenarioFile) {
  auto error_of = [&](const char* path, const char* body) {
    const auto r = p().http().Post(path, body, "application/json");
    EXPECT_EQ(status(r), 400) << path << " " << body;
    return LivePlant::json_of(r)["error"].get<std::string>();
  };
  EXPECT_EQ(error_of("/api/nodes/dsv/sdo/read", R"({"index": "0x1018", "subindex": 1})"),
            "<body>:1:21: unknown key 'subindex' in the SDO read (known: index, sub)");
  EXPECT_EQ(error_of("/api/nmt", R"({"command": "start", "node": "dsv", "node": "md2"})"),
            "<body>:1:37: the NMT command: duplicate key 'node'");
  EXPECT_EQ(error_of("/api/nmt", R"({"command": "start", "node": [2]})"), "<body>:1:30: node: a node's name or 0");
  EXPECT_EQ(error_of("/api/clock", R"({"action": "run", "ms": "soon"})"), "<body>:1:25: ms: 'soon' is not an integer");
  EXPECT_EQ(error_of("/api/frames", R"({"id": 1792, "data": "0F0"})"), "<body>:1:22: data: '0F0' is not a sequence of hex bytes");
  EXPECT_EQ(error_of("/api/sync", R"({"period_ms": 10, "overflow": 4})"),
            "<body>:1:19: unknown key 'overflow' in the SYNC producer (known: bus, period_ms, counter_overflow)");
  // The same fields spelt right are taken: integers as numbers or text in the scenario's syntax.
  EXPECT_EQ(status(p().post("/api/nodes/dsv/sdo/read", {{"index", "0x1018"}, {"sub", 1}})), 200);
  EXPECT_EQ(status(p().post("/api/frames", {{"id", 0x700}, {"data", "0f 00"}})), 200);
}

TEST_F(ControlApi, ForeignHostOrOriginIsRefused) {
  const std::string self = "127.0.0.1:" + std::to_string(p().port());
  auto r = p().http().Get("/api/nodes", {{"Host", "evil.example:" + std::to_string(p().port())}});
  EXPECT_EQ(status(r), 403);
  EXPECT_EQ(status(p().http().Get("/api/nodes", {{"Host", "127.0.0.1:1"}})), 403);
  EXPECT_EQ(status(p().http().Get("/api/nodes", {{"Origin", "http://evil.example"}})), 403);
  EXPECT_EQ(status(p().http().Get("/api/nodes", {{"Origin", "http://" + self}})), 200);
  EXPECT_EQ(status(p().http().Get("/api/nodes", {{"Host", "localhost:" + std::to_string(p().port())}})), 200);
  // A refused write changes nothing.
  const auto t = get("/api/clock")["t_us"];
  EXPECT_EQ(status(p().http().Post("/api/clock", {{"Origin", "http://evil.example"}}, R"({"action":"run","ms":10})",
                                   "application/json")),
            403);
  std::this_thread::sleep_for(std::chrono::milliseconds(30));
  EXPECT_EQ(get("/api/clock")["t_us"], t);
}

}  // namespace
