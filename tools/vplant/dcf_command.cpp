// `vplant dcf SCENARIO NODE`: the CiA 306 DCF of one node of a scenario, with the values and the
// node-ID the scenario configures (engine/reporting/node_dcf.h). Exit 2 for a bad file, an unknown node or
// an output that cannot be written.
#include <cstdio>
#include <memory>
#include <string>

#include "engine/running/environment.h"
#include "engine/reporting/node_dcf.h"
#include "engine/loading/scenario_loader.h"
#include "tools/vplant/commands.h"
#include "tools/vplant/exit_codes.h"
#include "tools/vplant/text_output.h"

namespace vplant {

namespace {

struct DcfArgs {
  std::string scenario;
  std::string node;
  std::string output;
};

int run_dcf(const DcfArgs& a) {
  std::string text;
  try {
    text = scenario::node_dcf(scenario::load_scenario_file(a.scenario), scenario::default_environment(), a.node);
  } catch (const scenario::LoadError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return kExitBadInput;
  }
  return write_text_output("vplant dcf", text, a.output);
}

}  // namespace

Runner add_dcf_command(CLI::App& app) {
  auto a = std::make_shared<DcfArgs>();
  app.add_option("scenario", a->scenario, "scenario file (YAML, see docs/scenarios.md)")->required();
  app.add_option("node", a->node, "the node's name in the scenario")->required();
  app.add_option("-o,--output", a->output, "write to FILE instead of stdout");
  return [a] { return run_dcf(*a); };
}

}  // namespace vplant
