// `vplant eds NAME`: a product's EDS file (generated from its emulated object dictionary).
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <string>

#include "devices/canopen/eds.h"
#include "devices/registry.h"
#include "tools/vplant/commands.h"
#include "tools/vplant/exit_codes.h"

namespace vplant {

namespace {

struct EdsOptions {
  std::string product;
  std::string variant;
  std::string output;
  std::string check;
};

// Prints every error and warning as file:line: ...; exit 2 on errors, 0 otherwise.
int check_file(const std::string& path) {
  const auto findings = canopen::check_eds_file(path);
  bool errors = false;
  for (const auto& f : findings) {
    std::fprintf(stderr, "%s\n", f.message().c_str());
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
  const std::string text = product->eds(o.variant);
  if (o.output.empty() || o.output == "-") {
    std::fwrite(text.data(), 1, text.size(), stdout);
    return kExitOk;
  }
  std::ofstream out(o.output, std::ios::binary);
  if (!(out << text)) {
    std::fprintf(stderr, "vplant eds: cannot write '%s'\n", o.output.c_str());
    return kExitBadInput;
  }
  return kExitOk;
}

}  // namespace

Runner add_eds_command(CLI::App& app) {
  auto o = std::make_shared<EdsOptions>();
  app.add_option("device", o->product, "product name (see `vplant devices`)");
  app.add_option("--check", o->check,
                 "check an EDS file: print its errors and warnings as file:line (strict: deviations that `node` and "
                 "`run` load with a warning are errors here)");
  app.add_option("--variant", o->variant, "product variant");
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
