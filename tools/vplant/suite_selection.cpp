#include "tools/vplant/suite_selection.h"

#include <fnmatch.h>

#include <algorithm>
#include <filesystem>

#include "engine/loading/scenario_cases.h"
#include "engine/loading/yaml_fields.h"

namespace vplant {

namespace fs = std::filesystem;

namespace {

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

bool is_scenario_name(const std::string& filename) {
  return ends_with(filename, ".yaml") && !ends_with(filename, ".plant.yaml") && filename[0] != '.';
}

}  // namespace

std::optional<Shard> parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  if (slash == std::string::npos) return std::nullopt;
  const auto k = scenario::parse_integer(text.substr(0, slash));
  const auto n = scenario::parse_integer(text.substr(slash + 1));
  if (!k || !n || *n < 1 || *k < 1 || *k > *n || *n > 100000) return std::nullopt;
  return Shard{static_cast<std::size_t>(*k), static_cast<std::size_t>(*n)};
}

std::vector<std::string> find_scenario_files(const std::vector<std::string>& paths, std::string& problem) {
  std::vector<std::string> files;
  for (const auto& path : paths) {
    std::error_code ec;
    const auto status = fs::status(path, ec);
    if (ec || !fs::exists(status)) {
      problem = path + ": no such file or folder";
      return {};
    }
    if (!fs::is_directory(status)) {
      files.push_back(fs::path(path).lexically_normal().string());
      continue;
    }
    auto it = fs::recursive_directory_iterator(path, fs::directory_options::skip_permission_denied, ec);
    for (; !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
      const std::string filename = it->path().filename().string();
      if (it->is_directory(ec) && filename[0] == '.') {
        it.disable_recursion_pending();
        continue;
      }
      if (it->is_regular_file(ec) && is_scenario_name(filename)) files.push_back(it->path().lexically_normal().string());
    }
    if (ec) {
      problem = path + ": " + ec.message();
      return {};
    }
  }
  std::sort(files.begin(), files.end());
  files.erase(std::unique(files.begin(), files.end()), files.end());
  return files;
}

std::vector<SuiteCase> expand_cases(const std::vector<std::string>& files) {
  std::vector<SuiteCase> cases;
  for (const auto& file : files) {
    try {
      const auto file_cases = scenario::ScenarioCases::load_file(file);
      for (std::size_t i = 0; i < file_cases.size(); ++i) cases.push_back({file, file_cases.name(i), {}});
    } catch (const scenario::LoadError& e) {
      cases.push_back({file, file, e.what()});
    }
  }
  return cases;
}

std::vector<SuiteCase> select_cases(const std::vector<SuiteCase>& cases, const std::string& glob, const Shard& shard) {
  std::vector<SuiteCase> selected;
  std::size_t position = 0;  // among the cases the filter kept
  for (const auto& c : cases) {
    if (!glob.empty() && ::fnmatch(glob.c_str(), c.name.c_str(), 0) != 0) continue;
    if (position++ % shard.count == shard.index - 1) selected.push_back(c);
  }
  return selected;
}

}  // namespace vplant
