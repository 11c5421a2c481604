// vplant::Simulation, the public API, on small scenarios of real products and on the reference
// plant: loading and its errors, the caller's endpoint and step function, time, signals, inputs,
// parameters, faults, the trace, and the reference plant's script giving `vplant run`'s trace.
#include <gtest/gtest.h>

#include <vplant/simulation.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <vector>

#include "engine/running/environment.h"
#include "engine/runner.h"
#include "engine/loading/scenario_loader.h"
#include "tests/support/temp_path.h"
#include "tests/support/read_file.h"

using namespace std::chrono_literals;

namespace {

// The zero-time bus: a request and its answer share the tick (the bit-timed default is tested below).
const std::string kSensor = R"(name: sensor
buses:
  - {name: main, transport: virtual, timing: ideal}
nodes:
  - {name: hlt, device: hlt1100, node_id: 5}
)";

using vtest::read_file;

vplant::Error load_error(const std::string& yaml) {
  try {
    vplant::Simulation::load_string(yaml, {}, "bad.yaml");
  } catch (const vplant::Error& e) {
    return e;
  }
  ADD_FAILURE() << "no error for:\n" << yaml;
  return vplant::Error("", 0, 0, "", "");
}

}  // namespace

TEST(Simulation, LoadErrorsCarryFileLineAndColumn) {
  const auto e = load_error("name: x\nnodes:\n  - {name: hlt, device: no_such_product}\n");
  EXPECT_EQ(e.file(), "bad.yaml");
  EXPECT_EQ(e.line(), 3);
  EXPECT_GT(e.column(), 0);
  EXPECT_NE(std::string(e.what()).find("bad.yaml:3:"), std::string::npos) << e.what();
  EXPECT_NE(e.reason().find("no_such_product"), std::string::npos) << e.reason();

  EXPECT_THROW(vplant::Simulation::load_file("/nonexistent/scenario.yaml"), vplant::Error);
}

TEST(Simulation, OnTheBitTimedBusTheAnswerTakesWireTime) {
  auto sim = vplant::Simulation::load_string(R"(name: sensor
buses:
  - {name: main, bitrate: 125000}
nodes:
  - {name: hlt, device: hlt1100, node_id: 5}
)");
  std::vector<vplant::TimedFrame> seen;
  auto& bus = sim.attach("main", [&](const vplant::Frame& f, vplant::Time t) { seen.push_back({t, "", f}); });
  sim.run_for(5ms);
  seen.clear();
  const auto asked = sim.now();
  bus.send(vplant::Frame::make(0x605, {0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0}));
  sim.run_for(3ms);
  ASSERT_EQ(seen.size(), 1u);
  EXPECT_EQ(seen[0].frame.id, 0x585u);
  // Two 8-byte frames at 125 kbit/s: at least 2 × 111 bits = 1.776 ms after the request.
  EXPECT_GE(seen[0].time - asked, std::chrono::microseconds(1776));
}

TEST(Simulation, RefusesSocketCanBusesAndRealTime) {
  const auto bus = load_error("buses:\n  - {name: main, transport: socketcan:vcan0}\nnodes:\n  - {name: hlt, device: hlt1100}\n");
  EXPECT_EQ(bus.line(), 2);
  EXPECT_NE(bus.reason().find("in-process"), std::string::npos) << bus.what();
  const auto clock = load_error(kSensor + "clock: {mode: realtime}\n");
  EXPECT_NE(clock.reason().find("virtual time"), std::string::npos) << clock.what();
}

TEST(Simulation, TheCallersEndpointReceivesAndSendsInTheSameTick) {
  auto sim = vplant::Simulation::load_string(kSensor);
  std::vector<vplant::TimedFrame> seen;
  auto& bus = sim.attach("main", [&](const vplant::Frame& f, vplant::Time t) { seen.push_back({t, "", f}); });
  EXPECT_EQ(bus.bus(), "main");
  sim.run_for(5ms);
  ASSERT_FALSE(seen.empty());
  EXPECT_EQ(seen.front().frame, vplant::Frame::make(0x705, {0x00}));  // boot-up
  EXPECT_EQ(sim.signal("hlt.nmt_state"), 127);

  // SDO upload of 1000h (device type): the answer arrives at the time of the request.
  seen.clear();
  const auto asked = sim.now();
  bus.send(vplant::Frame::make(0x605, {0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0}));
  sim.run_for(1ms);
  ASSERT_EQ(seen.size(), 1u);
  EXPECT_EQ(seen[0].frame.id, 0x585u);
  EXPECT_EQ(seen[0].frame.data[0], 0x43);
  EXPECT_EQ(seen[0].time, asked);

  bus.send(vplant::Frame::make(0x000, {0x01, 0x05}));
  sim.run_for(1ms);
  EXPECT_EQ(sim.signal("hlt.nmt_state"), 5);
  // The trace holds every frame, the caller's own included.
  const auto& trace = sim.trace();
  ASSERT_GE(trace.size(), 4u);
  EXPECT_EQ(vplant::to_candump(trace[0]), "(0000000000.000000) main 705#00");
}

TEST(Simulation, StepFunctionsRunEveryTickInOrder) {
  auto sim = vplant::Simulation::load_string(kSensor);
  std::vector<vplant::Time> first, second;
  sim.add_step([&](vplant::Time now, vplant::Duration tick) {
    EXPECT_EQ(tick, 1ms);
    first.push_back(now);
  });
  sim.add_step([&](vplant::Time now, vplant::Duration) {
    EXPECT_EQ(first.size(), second.size() + 1);
    second.push_back(now);
  });
  sim.run_for(50ms);
  ASSERT_EQ(first.size(), 50u);
  EXPECT_EQ(first.front(), 0ms);
  EXPECT_EQ(first.back(), 49ms);
  EXPECT_EQ(sim.now(), 50ms);
  EXPECT_EQ(second, first);
  sim.run_for(1500us);  // whole ticks: rounded up
  EXPECT_EQ(sim.now(), 52ms);
}

TEST(Simulation, RunUntilStopsWhenTheConditionHoldsOrAtTheTimeout) {
  auto sim = vplant::Simulation::load_string(kSensor);
  EXPECT_TRUE(sim.run_until([&] { return sim.now() >= 7ms; }, 1s));
  EXPECT_EQ(sim.now(), 7ms);
  EXPECT_FALSE(sim.run_until([] { return false; }, 20ms));
  EXPECT_EQ(sim.now(), 27ms);
}

TEST(Simulation, InputsSignalsAndTheirErrors) {
  auto sim = vplant::Simulation::load_string(kSensor);
  auto& bus = sim.attach("", nullptr);
  sim.set_input("hlt", "position", 0.1234);
  sim.run_for(5ms);  // boot-up
  bus.send(vplant::Frame::make(0x000, {0x01, 0x00}));
  sim.run_for(5ms);
  // Asked for after the frame went by: TPDO1 on entering Operational, 6020h:01 in 0.1 mm steps.
  EXPECT_EQ(sim.signal("frame(0x185)[0:4] as i32"), 1234);
  EXPECT_DOUBLE_EQ(sim.signal("hlt.position * 1000"), 123.4);

  EXPECT_THROW(sim.set_input("nobody", "position", 1), vplant::Error);
  EXPECT_THROW(sim.set_input("hlt", "no_such_input", 1), vplant::Error);
  try {
    sim.signal("hlt.no_such_port");
    ADD_FAILURE();
  } catch (const vplant::Error& e) {
    EXPECT_EQ(e.file(), "<signal>");
    EXPECT_NE(e.reason().find("no_such_port"), std::string::npos) << e.what();
  }
  EXPECT_THROW(sim.signal("frame(0x185)[0:"), vplant::Error);
  EXPECT_THROW(sim.parameter("cyl.bore_diameter"), vplant::Error);  // no plant
  EXPECT_THROW(sim.attach("other", nullptr), vplant::Error);
}

TEST(Simulation, FaultsAreAppliedNowWithTheScriptsSyntax) {
  auto sim = vplant::Simulation::load_string(kSensor);
  auto& bus = sim.attach("", nullptr);
  bus.send(vplant::Frame::make(0x000, {0x01, 0x00}));
  sim.run_for(5ms);
  sim.inject_fault("{device_fault: {node: hlt, fault: magnet_lost}}");
  sim.run_for(5ms);
  bool emcy = false;
  for (const auto& f : sim.trace())
    emcy |= f.frame.id == 0x085 && f.frame.data[0] == 0x00 && f.frame.data[1] == 0xFF && f.time >= 5ms;
  EXPECT_TRUE(emcy) << "no EMCY FF00h after magnet_lost";

  try {
    sim.inject_fault("{device_fault: {node: hlt, fault: no_such_fault}}");
    ADD_FAILURE();
  } catch (const vplant::Error& e) {
    EXPECT_EQ(e.file(), "<fault>");
    EXPECT_NE(e.reason().find("no_such_fault"), std::string::npos) << e.what();
  }
  try {
    sim.inject_fault("{device_fault: {node: hlt,\n  fault: [}");
    ADD_FAILURE();
  } catch (const vplant::Error& e) {
    EXPECT_EQ(e.file(), "<fault>");
    EXPECT_EQ(e.line(), 2);
  }
}

TEST(Simulation, PlantParametersByName) {
  auto sim = vplant::Simulation::load_file(VPLANT_REFERENCE_PLANT);
  EXPECT_DOUBLE_EQ(sim.parameter("cyl.bore_diameter"), 0.063);
  sim.set_parameter("cyl.load_force", 1000);
  EXPECT_DOUBLE_EQ(sim.parameter("cyl.load_force"), 1000);
  EXPECT_THROW(sim.set_parameter("cyl.bore_diameter", -1), vplant::Error);
  EXPECT_THROW(sim.parameter("cyl.no_such_parameter"), vplant::Error);
}

// The reference plant with its own script, in-process: every assertion holds and the trace is
// byte for byte the one the engine behind `vplant run` writes for the same file.
TEST(Simulation, TheReferencePlantsScriptGivesTheTraceOfVplantRun) {
  const auto lib_trace = vtest::unique_temp_path("api_lib", ".log");
  const auto cli_trace = vtest::unique_temp_path("api_cli", ".log");
  {
    vplant::Options o;
    o.run_script = true;
    o.trace_file = lib_trace;
    auto sim = vplant::Simulation::load_file(VPLANT_REFERENCE_PLANT, o);
    sim.run_for(6s);
    EXPECT_TRUE(sim.script_finished());
    EXPECT_GT(sim.assertions(), 10u);
    EXPECT_TRUE(sim.failures().empty()) << sim.failures().front();
  }
  {
    auto s = scenario::load_scenario_file(VPLANT_REFERENCE_PLANT);
    s.outputs = {};  // no CSV or plots in the test's directory
    scenario::RunOptions o;
    o.quiet = true;
    o.trace = cli_trace;
    scenario::Runner runner(s, scenario::default_environment(), o);
    EXPECT_EQ(runner.run(), 0);
  }
  const auto lib = read_file(lib_trace), cli = read_file(cli_trace);
  std::remove(lib_trace.c_str());
  std::remove(cli_trace.c_str());
  EXPECT_GT(lib.size(), 100000u);
  EXPECT_TRUE(lib == cli) << "the library's trace differs from vplant run's";
}

TEST(Simulation, RunningFromAStepOrAFrameHandlerThrows) {
  auto sim = vplant::Simulation::load_string(kSensor);
  std::string from_step, from_handler;
  sim.add_step([&](vplant::Time, vplant::Duration) {
    if (!from_step.empty()) return;
    try {
      sim.run_for(1ms);
      from_step = "(ran)";
    } catch (const vplant::Error& e) {
      from_step = e.what();
    }
  });
  auto& bus = sim.attach("main", [&](const vplant::Frame&, vplant::Time) {
    if (!from_handler.empty()) return;
    try {
      sim.run_until([] { return false; }, 1ms);
      from_handler = "(ran)";
    } catch (const vplant::Error& e) {
      from_handler = e.what();
    }
  });
  bus.send(vplant::Frame::make(0x605, {0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0}));
  sim.run_for(3ms);
  EXPECT_NE(from_step.find("run_for: called from a step function or frame handler"), std::string::npos) << from_step;
  EXPECT_NE(from_handler.find("run_until: called from a step function or frame handler"), std::string::npos)
      << from_handler;
  EXPECT_EQ(sim.now(), 3ms);  // the nested calls advanced nothing
  sim.run_for(1ms);           // and the simulation still runs from the caller's code
  EXPECT_EQ(sim.now(), 4ms);
}

TEST(Simulation, FramesClassicCanCannotCarryAreRefusedWithTheRange) {
  auto sim = vplant::Simulation::load_string(kSensor);
  auto& bus = sim.attach("main", nullptr);
  for (std::uint8_t dlc : {9, 12, 15, 200}) {
    vplant::Frame f;
    f.id = 0x605;
    f.dlc = dlc;
    try {
      bus.send(f);
      ADD_FAILURE() << "DLC " << int(dlc) << " was sent";
    } catch (const vplant::Error& e) {
      EXPECT_NE(std::string(e.what()).find("DLC " + std::to_string(dlc) + " is out of range: a classic CAN frame has DLC 0..8"),
                std::string::npos)
          << e.what();
    }
  }
  vplant::Frame high;
  high.id = 0x800;
  EXPECT_THROW(bus.send(high), vplant::Error);  // 11-bit identifier above 7FFh
  high.extended = true;
  EXPECT_NO_THROW(bus.send(high));
  high.id = 0x20000000;
  EXPECT_THROW(bus.send(high), vplant::Error);

  try {
    vplant::Frame::make(0x605, {1, 2, 3, 4, 5, 6, 7, 8, 9});
    ADD_FAILURE() << "nine bytes made a frame";
  } catch (const vplant::Error& e) {
    EXPECT_NE(std::string(e.what()).find("9 data bytes are out of range: a classic CAN frame has 0..8"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(vplant::Frame::make(0x20000000, {}), vplant::Error);
  EXPECT_TRUE(vplant::Frame::make(0x1FFFFFFF, {}).extended);
}

TEST(Simulation, AnUnknownPlantParameterListsTheValidNames) {
  auto sim = vplant::Simulation::load_file(VPLANT_REFERENCE_PLANT);
  // The header's example.
  EXPECT_DOUBLE_EQ(sim.parameter("cyl.bore_diameter"), 0.063);
  for (const std::string name : {"cyl.bore", "nothing.at_all"}) {
    try {
      (void)sim.parameter(name);
      ADD_FAILURE() << name;
    } catch (const vplant::Error& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("no parameter '" + name + "'"), std::string::npos) << what;
      EXPECT_NE(what.find("cyl.bore_diameter, cyl.rod_diameter, cyl.stroke"), std::string::npos) << what;
    }
  }
  try {
    sim.set_parameter("cyl.bore", 0.05);
    ADD_FAILURE() << "set cyl.bore";
  } catch (const vplant::Error& e) {
    EXPECT_NE(std::string(e.what()).find("cyl.bore_diameter"), std::string::npos) << e.what();
  }
}
