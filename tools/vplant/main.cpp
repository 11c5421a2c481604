// vplant: emulated CANopen devices and a hydraulic plant on SocketCAN or a virtual bus.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <map>
#include <string>

#include "tools/vplant/commands.h"
#include "tools/vplant/exit_codes.h"

int main(int argc, char** argv) {
  CLI::App app{"vplant: a virtual hydraulic plant of emulated CANopen devices"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "vplant 0.1.0");

  std::map<CLI::App*, vplant::Runner> runners;
  auto add = [&](const char* name, const char* help, vplant::Runner (*fn)(CLI::App&)) {
    auto* sub = app.add_subcommand(name, help);
    runners[sub] = fn(*sub);
  };
  add("node", "run one emulated node (a product or any EDS file)", vplant::add_node_command);
  add("eds", "print a product's EDS file, or check an EDS file", vplant::add_eds_command);
  add("devices", "list the emulated products", vplant::add_devices_command);
  add("run", "run a scenario: the whole plant, a scripted master, faults and checks", vplant::add_run_command);
  add("dcf", "write the DCF of a scenario's node: its configured values and node-ID", vplant::add_dcf_command);
  add("test", "run a suite of scenarios: folders, -j in parallel, shards, one JUnit, a report", vplant::add_test_command);
  add("classroom", "one plant per trainee: seats with their own links, a trainer's overview (docs/classroom.md)",
      vplant::add_classroom_command);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? vplant::kExitOk : vplant::kExitBadInput;
  }
  for (auto* sub : app.get_subcommands()) {
    if (auto it = runners.find(sub); it != runners.end()) return it->second();
  }
  return vplant::kExitBadInput;
}
