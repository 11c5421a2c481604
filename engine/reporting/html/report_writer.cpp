#include "engine/reporting/html/report_writer.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>

#include <nlohmann/json.hpp>

#include "engine/reporting/junit_writer.h"
#include "sim/can_frame.h"

#if VPLANT_HAVE_DASHBOARD
#include "dashboard/assets.h"
#endif

namespace scenario::report {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr int kVersion = 1;
// A case.json larger than this is not a summary vplant wrote.
constexpr std::uintmax_t kMaxSummaryBytes = 1 << 20;

// Six significant digits: what a plot or a table shows, a third of the digits of a full double.
double short_value(double v) {
  if (!std::isfinite(v) || v == 0) return v;
  const double scale = std::pow(10.0, 5 - static_cast<int>(std::floor(std::log10(std::fabs(v)))));
  return std::round(v * scale) / scale;
}

std::string result_of(int exit_code) { return exit_code == 0 ? "passed" : exit_code == 1 ? "failed" : "error"; }

std::string where(const SourceMark& m) {
  return m.file + ":" + std::to_string(m.line) + ":" + std::to_string(m.column);
}

// Writes `text` to `path` through a temporary file in the same folder and a rename.
std::string write_file(const fs::path& path, std::string_view text) {
  std::error_code ec;
  fs::create_directories(path.parent_path(), ec);
  if (ec) return "cannot create '" + path.parent_path().string() + "': " + ec.message();
  const fs::path tmp = path.string() + ".tmp" + std::to_string(::getpid());
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) return "cannot write '" + tmp.string() + "': " + std::strerror(errno);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.close();
    if (!out) {
      fs::remove(tmp, ec);
      return "cannot write '" + tmp.string() + "'";
    }
  }
  fs::rename(tmp, path, ec);
  if (ec) {
    fs::remove(tmp, ec);
    return "cannot write '" + path.string() + "': " + ec.message();
  }
  return {};
}

std::string write_assets(const fs::path& dir) {
#if VPLANT_HAVE_DASHBOARD
  for (const char* name : {"report.js", "report.css"}) {
    const auto* asset = dashboard::find_asset(std::string("/report/") + name);
    if (!asset) return std::string("this vplant has no report asset ") + name + " (a broken build)";
    if (auto error = write_file(dir / "assets" / name, asset->body); !error.empty()) return error;
  }
  return {};
#else
  (void)dir;
  return "this vplant was built without the dashboard (-DVPLANT_DASHBOARD=OFF), which draws the report";
#endif
}

// JSON inside <script type="application/json">: "</script" or "<!--" must not appear in it.
std::string script_json(const json& j) {
  std::string text = j.dump(-1, ' ', false, json::error_handler_t::replace);
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    // '<' occurs only inside JSON strings, where \u003C reads back as '<'.
    if (c == '<') out += "\\u003C";
    else out += c;
  }
  return out;
}

// The title goes through the JUnit writer's XML escape, which serves HTML text as well.
std::string page(const std::string& title, const std::string& assets, const std::string& data_id, const json& data) {
  return "<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" +
         xml_escape(title) + "</title>\n<link rel=\"icon\" href=\"data:,\">\n<link rel=\"stylesheet\" href=\"" + assets +
         "report.css\">\n<script defer src=\"" + assets + "report.js\"></script>\n</head>\n<body>\n<script type=\"application/json\" id=\"" +
         data_id + "\">" + script_json(data) +
         "</script>\n<main id=\"report\"><noscript>The report needs JavaScript.</noscript></main>\n</body>\n</html>\n";
}

json outcome_json(const Outcome& o) {
  json j = {{"name", o.name}, {"where", where(o.mark)}, {"passed", o.passed}, {"t", sim::seconds(o.time)}};
  if (!o.passed) {
    j["expected"] = o.expected;
    j["actual"] = o.actual;
  }
  return j;
}

std::string hex_bytes(const sim::CanFrame& f) {
  static const char* digits = "0123456789ABCDEF";
  std::string s;
  for (auto b : f.payload()) {
    s += digits[b >> 4];
    s += digits[b & 15];
  }
  return s;
}

// One frame as a row [t_us, bus, id, flags (1 extended, 2 remote), dlc, data, service, node, text]:
// a third of the size of an object per frame. dashboard/src/report/trace_rows.ts reads it back.
json frame_row(const CaseRecord::Frame& f, std::size_t bus) {
  return json::array({f.t_us, bus, f.frame.id, (f.frame.extended ? 1 : 0) | (f.frame.rtr ? 2 : 0), f.frame.dlc,
                      hex_bytes(f.frame), canopen::service_name(f.decoded.service, f.decoded.pdo),
                      f.decoded.node > 0 ? json(f.decoded.node) : json(nullptr), f.decoded.text});
}

json summary_json(const std::string& id, const CaseRecord& r) {
  std::size_t failures = 0;
  json first_failure = nullptr;
  for (const auto& o : r.outcomes) {
    if (o.passed) continue;
    if (!failures) first_failure = outcome_json(o);
    ++failures;
  }
  std::size_t faults = 0;
  for (const auto& e : r.events) faults += e.kind == "fault";
  return {{"version", kVersion},
          {"id", id},
          {"name", r.name},
          {"file", r.file},
          {"result", result_of(r.exit_code)},
          {"exit_code", r.exit_code},
          {"error", r.error},
          {"simulated_s", r.simulated_s},
          {"wall_s", r.wall_s},
          {"seed", r.seed},
          {"interrupted", r.interrupted},
          {"assertions", r.outcomes.size() + r.outcomes_left_out},
          {"failures", failures},
          {"first_failure", first_failure},
          {"faults", faults},
          {"frames", r.frames_seen},
          {"page", "cases/" + id + "/index.html"}};
}

json case_json(const json& summary, const CaseRecord& r) {
  json j = summary;
  json outcomes = json::array();
  for (const auto& o : r.outcomes) outcomes.push_back(outcome_json(o));
  j["outcomes"] = std::move(outcomes);
  j["outcomes_left_out"] = r.outcomes_left_out;
  json nodes = json::array();
  for (const auto& n : r.nodes) nodes.push_back({{"name", n.name}, {"bus", n.bus}, {"node_id", n.node_id}});
  j["nodes"] = std::move(nodes);

  json times = json::array();
  for (double t : r.times) times.push_back(std::round(t * 1e6) / 1e6);
  json values = json::array();
  for (const auto& series : r.values) {
    json v = json::array();
    for (double x : series) v.push_back(std::isfinite(x) ? json(short_value(x)) : json(nullptr));
    values.push_back(std::move(v));
  }
  j["signals"] = {{"names", r.signals}, {"t", std::move(times)}, {"values", std::move(values)}};
  json plots = json::array();
  for (const auto& p : r.plots)
    plots.push_back({{"title", p.title}, {"y_label", p.y_label}, {"labels", p.labels}, {"series", p.series}});
  j["plots"] = std::move(plots);

  std::vector<std::string> wires;
  json rows = json::array();
  for (const auto& f : r.frames) {
    auto it = std::find(wires.begin(), wires.end(), f.bus);
    if (it == wires.end()) it = wires.insert(wires.end(), f.bus);
    rows.push_back(frame_row(f, static_cast<std::size_t>(it - wires.begin())));
  }
  j["trace"] = {{"seen", r.frames_seen}, {"buses", wires}, {"rows", std::move(rows)}};

  json buses = json::array();
  for (const auto& b : r.buses) {
    json ids = json::array();
    for (const auto& i : b.ids)
      ids.push_back({{"id", i.id}, {"ext", i.extended}, {"frames", i.frames}, {"load", short_value(i.load)}});
    buses.push_back({{"name", b.name},
                     {"wire", b.wire},
                     {"bit_rate", b.bit_rate},
                     {"frames", b.frames},
                     {"error_frames", b.error_frames},
                     {"tx_queue_overflow", b.tx_queue_overflow},
                     {"mean_load", short_value(b.mean_load)},
                     {"ids", std::move(ids)}});
  }
  j["buses"] = std::move(buses);

  json events = json::array();
  for (const auto& e : r.events) events.push_back({{"t", e.t}, {"kind", e.kind}, {"text", e.text}});
  j["events"] = std::move(events);
  j["events_left_out"] = r.events_left_out;
  return j;
}

}  // namespace

std::string case_id(const std::string& name) {
  std::string id;
  for (char c : name) id += std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-' ? c : '_';
  if (id.empty()) return "case";
  if (id.find_first_not_of('.') == std::string::npos) id = "_" + id;
  return id;
}

std::string write_case(const std::string& dir, const CaseRecord& record) {
  const fs::path root(dir);
  if (auto error = write_assets(root); !error.empty()) return error;
  const std::string id = case_id(record.name);
  const fs::path folder = root / "cases" / id;
  const json summary = summary_json(id, record);
  if (auto error = write_file(folder / "index.html", page(record.name + " - vplant report", "../../assets/", "case-data",
                                                          case_json(summary, record)));
      !error.empty())
    return error;
  // Last: the index lists a case once its page is there.
  return write_file(folder / "case.json", summary.dump(2) + "\n");
}

std::string write_index(const std::string& dir) {
  const fs::path root(dir);
  if (auto error = write_assets(root); !error.empty()) return error;
  json cases = json::array();
  std::error_code ec;
  std::vector<fs::path> folders;
  for (fs::directory_iterator it(root / "cases", ec), end; !ec && it != end; it.increment(ec))
    if (it->is_directory()) folders.push_back(it->path());
  std::sort(folders.begin(), folders.end());
  for (const auto& folder : folders) {
    const fs::path file = folder / "case.json";
    const std::string id = folder.filename().string();
    json broken = {{"version", kVersion}, {"id", id}, {"name", id}, {"result", "error"}, {"exit_code", 2},
                   {"page", "cases/" + id + "/index.html"}};
    std::error_code size_ec;
    const auto size = fs::file_size(file, size_ec);
    if (size_ec || size > kMaxSummaryBytes) {
      broken["error"] = size_ec ? "no case.json (the case did not finish)" : "case.json is too large to be a summary";
      cases.push_back(std::move(broken));
      continue;
    }
    std::ifstream in(file, std::ios::binary);
    json j = json::parse(in, nullptr, false);
    if (j.is_discarded() || !j.is_object() || !j.contains("name") || !j.contains("result")) {
      broken["error"] = "case.json is not a case summary";
      cases.push_back(std::move(broken));
      continue;
    }
    j["id"] = id;
    j["page"] = "cases/" + id + "/index.html";
    cases.push_back(std::move(j));
  }
  return write_file(root / "index.html", page("vplant report", "assets/", "index-data", json{{"version", kVersion}, {"cases", cases}}));
}

}  // namespace scenario::report
