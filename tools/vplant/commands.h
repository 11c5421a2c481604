// Subcommands of the vplant command line. Each registers its options on a CLI11 subcommand and
// returns a runner invoked after parsing.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>

namespace vplant {

using Runner = std::function<int()>;

Runner add_node_command(CLI::App& app);
Runner add_eds_command(CLI::App& app);
Runner add_devices_command(CLI::App& app);
Runner add_run_command(CLI::App& app);
Runner add_dcf_command(CLI::App& app);
Runner add_test_command(CLI::App& app);
Runner add_classroom_command(CLI::App& app);

}  // namespace vplant
