#include "engine/reporting/junit_merge.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "engine/reporting/junit_writer.h"

namespace scenario {

namespace {

/// The value of attribute `name` in an opening tag ("" when absent).
std::string attribute(const std::string& tag, const std::string& name) {
  const std::string key = " " + name + "=\"";
  const auto at = tag.find(key);
  if (at == std::string::npos) return {};
  const auto start = at + key.size();
  const auto end = tag.find('"', start);
  return end == std::string::npos ? std::string() : tag.substr(start, end - start);
}

}  // namespace

std::vector<std::string> junit_testsuites(const std::string& xml) {
  std::vector<std::string> suites;
  std::size_t pos = 0;
  for (;;) {
    pos = xml.find("<testsuite", pos);
    if (pos == std::string::npos) return suites;
    const char next = pos + 10 < xml.size() ? xml[pos + 10] : '\0';
    if (next != ' ' && next != '>' && next != '\n' && next != '\t') {  // <testsuites>
      pos += 10;
      continue;
    }
    const auto tag_end = xml.find('>', pos);
    if (tag_end == std::string::npos) return suites;
    std::size_t end = tag_end + 1;
    if (xml[tag_end - 1] != '/') {
      const auto close = xml.find("</testsuite>", tag_end);
      if (close == std::string::npos) return suites;
      end = close + 12;
    }
    suites.push_back(xml.substr(pos, end - pos));
    pos = end;
  }
}

std::string junit_error_suite(const std::string& name, const std::string& message, const std::string& output,
                              double wall_seconds) {
  const std::string n = xml_escape(name);
  char time[32];
  std::snprintf(time, sizeof time, "%.3f", wall_seconds);
  return "<testsuite name=\"" + n + "\" tests=\"1\" failures=\"0\" errors=\"1\" time=\"" + time + "\">\n" +
         "    <testcase classname=\"" + n + "\" name=\"run\" time=\"" + time + "\">\n" + "      <error message=\"" +
         xml_escape(message) + "\">" + xml_escape(output) + "</error>\n    </testcase>\n  </testsuite>";
}

std::string write_merged_junit(const std::string& path, const std::vector<std::string>& testsuites) {
  long tests = 0, failures = 0, errors = 0;
  double time = 0;
  for (const auto& s : testsuites) {
    const std::string tag = s.substr(0, s.find('>'));
    tests += std::atol(attribute(tag, "tests").c_str());
    failures += std::atol(attribute(tag, "failures").c_str());
    errors += std::atol(attribute(tag, "errors").c_str());
    time += std::atof(attribute(tag, "time").c_str());
  }
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) return "cannot write '" + path + "': " + std::strerror(errno);
  std::fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
  std::fprintf(f, "<testsuites tests=\"%ld\" failures=\"%ld\" errors=\"%ld\" time=\"%.3f\">\n", tests, failures, errors, time);
  for (const auto& s : testsuites) std::fprintf(f, "  %s\n", s.c_str());
  std::fprintf(f, "</testsuites>\n");
  const bool failed = std::ferror(f) != 0;
  if (std::fclose(f) != 0 || failed) return "cannot write '" + path + "': " + std::strerror(errno);
  return {};
}

}  // namespace scenario
