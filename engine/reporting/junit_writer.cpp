#include "engine/reporting/junit_writer.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace scenario {

std::string xml_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t') out += ' ';
        else out += c;
    }
  }
  return out;
}

std::string write_junit(const std::string& path, const std::string& suite, const Verdicts& verdicts, double wall_seconds,
                        double simulated_seconds) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) return "cannot write '" + path + "': " + std::strerror(errno);
  std::fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
  std::fprintf(f, "<testsuites tests=\"%zu\" failures=\"%zu\" time=\"%.3f\">\n", verdicts.outcomes().size(),
               verdicts.failures(), wall_seconds);
  std::fprintf(f, "  <testsuite name=\"%s\" tests=\"%zu\" failures=\"%zu\" errors=\"0\" time=\"%.3f\">\n",
               xml_escape(suite).c_str(), verdicts.outcomes().size(), verdicts.failures(), wall_seconds);
  std::fprintf(f, "    <properties><property name=\"simulated_seconds\" value=\"%.6f\"/></properties>\n", simulated_seconds);
  for (const auto& o : verdicts.outcomes()) {
    const std::string where = o.mark.to_string();
    std::fprintf(f, "    <testcase classname=\"%s\" name=\"%s\" file=\"%s\" line=\"%d\" time=\"0\"", xml_escape(suite).c_str(),
                 xml_escape(o.name).c_str(), xml_escape(o.mark.file).c_str(), o.mark.line);
    if (o.passed) {
      std::fprintf(f, "/>\n");
      continue;
    }
    char t[32];
    std::snprintf(t, sizeof t, "%.6f", static_cast<double>(o.time.time_since_epoch().count()) * 1e-6);
    const std::string msg = "at t=" + std::string(t) + " s: expected " + o.expected + ", actual " + o.actual;
    std::fprintf(f, ">\n      <failure message=\"%s\">%s: %s</failure>\n    </testcase>\n", xml_escape(msg).c_str(),
                 xml_escape(where).c_str(), xml_escape(msg).c_str());
  }
  std::fprintf(f, "  </testsuite>\n</testsuites>\n");
  return std::fclose(f) == 0 ? std::string() : "cannot write '" + path + "': " + std::strerror(errno);
}

}  // namespace scenario
