// `vplant eds NAME`: a product's EDS file (generated from its emulated object dictionary), as it
// leaves the factory or, with --setting/--node-id, as that configuration has it.
#include <algorithm>
#include <cstdio>
#include <vector>
#include <string>

#include "devices/canopen/eds.h"
#include "devices/configured_eds.h"
#include "devices/registry.h"
#include "tools/vplant/commands.h"
#include "tools/vplant/exit_codes.h"
#include "tools/vplant/key_value.h"
#include "tools/vplant/text_output.h"

namespace vplant {

namespace {

struct EdsOptions {
  std::string product;
  std::string variant;
  std::vector<std::string> settings;
  int node_id = 0;
  std::string output;
  std::string check;
};

// Prints every error and warning as file:line: ...; exit 2 on errors, 0 otherwise.
int check_file(const std::string& path) {
  const auto findings = canopen::check_eds_file(path);
  bool errors = false;
  for (const auto& f : findings) {
    std::fprintf(stderr, "%s\n", f.to_string().c_str());
    errors = errors || !f.warning;
  }
  if (findings.empty()) std::fprintf(stderr, "%s: ok\n", path.c_str());
  return errors ? kExitBadInput : kExitOk;
}

int run_eds(const EdsOptions& o) {
  if (!o.check.empty()) return check_file(o.check);
  if (o.product.empty()) {
    std::fprintf(stderr, "vplant eds: give a device name or --check FILE\n");
    return kExitBadInput;
  }
  const auto* product = devices::find_product(o.product);
  if (!product) {
    std::fprintf(stderr, "vplant eds: unknown device '%s' (see `vplant devices`)\n", o.product.c_str());
    return kExitBadInput;
  }
  if (!o.variant.empty() && std::find(product->variants.begin(), product->variants.end(), o.variant) == product->variants.end()) {
    std::fprintf(stderr, "vplant eds: device '%s' has no variant '%s'\n", o.product.c_str(), o.variant.c_str());
    return kExitBadInput;
  }
  std::string text;
  if (o.settings.empty() && o.node_id == 0) {
    text = product->eds(o.variant);
  } else {
    devices::DeviceOptions options;
    options.variant = o.variant;
    options.node_id = static_cast<std::uint8_t>(o.node_id);
    std::string error;
    if (!parse_key_values(o.settings, options.settings, error)) {
      std::fprintf(stderr, "vplant eds: --setting %s\n", error.c_str());
      return kExitBadInput;
    }
    text = devices::configured_eds(*product, options, error);
    if (text.empty()) {
      std::fprintf(stderr, "vplant eds: %s\n", error.c_str());
      return kExitBadInput;
    }
  }
  return write_text_output("vplant eds", text, o.output);
}

}  // namespace

Runner add_eds_command(CLI::App& app) {
  auto o = std::make_shared<EdsOptions>();
  app.add_option("device", o->product, "product name (see `vplant devices`)");
  app.add_option("--check", o->check,
                 "check an EDS file: print its errors and warnings as file:line (strict: deviations that `node` and "
                 "`run` load with a warning are errors here)");
  app.add_option("--variant", o->variant, "product variant");
  app.add_option("--setting", o->settings,
                 "knob=value: the EDS of the node with this configuration setting, e.g. its PDO mapping (repeatable)");
  app.add_option("--node-id", o->node_id, "write node-relative values (COB-IDs) for this node-ID")->check(CLI::Range(1, 127));
  app.add_option("-o,--output", o->output, "write to FILE instead of stdout");
  return [o] { return run_eds(*o); };
}

Runner add_devices_command(CLI::App& app) {
  (void)app;
  return [] {
    for (const auto& p : devices::products()) {
      std::string variants;
      for (const auto& v : p.variants) variants += (variants.empty() ? " [" : ", ") + v;
      if (!variants.empty()) variants += "]";
      std::printf("%-10s %s%s\n", p.name.c_str(), p.description.c_str(), variants.c_str());
    }
    return kExitOk;
  };
}

}  // namespace vplant
