#include "engine/reporting/bus_report.h"

#include <algorithm>
#include <cstdio>

namespace scenario {

std::string describe_bus_load(const sim::Bus& bus, double simulated_s, std::size_t top_ids) {
  const double bit_s = 1.0 / static_cast<double>(bus.timing_bit_rate());
  const auto& st = bus.stats();
  char line[256];
  std::string out;
  std::snprintf(line, sizeof line, "    %s timing at %u kbit/s: load %.1f %% (mean), %.1f %% (last 100 ms)",
                bus.timing() == sim::BusTiming::Bit ? "bit" : "ideal", bus.timing_bit_rate() / 1000, bus.mean_load() * 100,
                bus.load() * 100);
  out += line;
  if (st.error_frames) out += ", error frames: " + std::to_string(st.error_frames);
  if (st.tx_queue_overflow) out += ", tx queue overflows: " + std::to_string(st.tx_queue_overflow);
  out += "\n";
  auto traffic = bus.traffic();
  if (traffic.empty() || simulated_s <= 0) return out;
  std::stable_sort(traffic.begin(), traffic.end(), [](const sim::IdTraffic& a, const sim::IdTraffic& b) { return a.bits > b.bits; });
  out += "    load by COB-ID:";
  for (std::size_t i = 0; i < traffic.size() && i < top_ids; ++i) {
    const auto& t = traffic[i];
    std::snprintf(line, sizeof line, "%s %0*X %.2f %% (%llu)", i ? "," : "", t.extended ? 8 : 3, t.id,
                  static_cast<double>(t.bits) * bit_s / simulated_s * 100, static_cast<unsigned long long>(t.frames));
    out += line;
  }
  if (traffic.size() > top_ids) out += ", " + std::to_string(traffic.size() - top_ids) + " more";
  out += "\n";
  return out;
}

}  // namespace scenario
