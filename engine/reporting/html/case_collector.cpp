#include "engine/reporting/html/case_collector.h"

#include <algorithm>

#include "engine/loading/signal_expression.h"

namespace scenario::report {

namespace {

std::string wire_name(const sim::Bus& bus) {
  return bus.transport() ? std::string(bus.transport()->name()) : bus.name();
}

}  // namespace

CaseCollector::CaseCollector(const Scenario& scenario, World& world, Recorder& recorder)
    : scenario_(scenario), world_(world), recorder_(recorder) {
  for (const auto& p : scenario.outputs.plots) {
    CaseRecord::Plot plot{p.title, p.y_label, {}, {}};
    for (std::size_t i = 0; i < p.signals.size(); ++i) {
      plot.labels.push_back(p.labels[i].empty() ? p.signals[i].text : p.labels[i]);
      plot.series.push_back(add_signal(p.signals[i]));
    }
    plots_.push_back(std::move(plot));
  }
  if (scenario.outputs.plots.empty()) {
    // One chart per signal: their units differ (metres, pascals, a fraction).
    const auto signals = scenario.outputs.csv && !scenario.outputs.csv->signals.empty() ? scenario.outputs.csv->signals
                                                                                        : world.wired_signals();
    for (std::size_t i = 0; i < signals.size() && i < kMaxDefaultSignals; ++i)
      plots_.push_back({signals[i].text, "", {signals[i].text}, {add_signal(signals[i])}});
  }
  CaseRecord::Plot load{"bus load", "load [%] (last 100 ms)", {}, {}};
  for (const auto& bus : world.buses()) {
    const std::string text = "bus." + bus->name() + ".load * 100";
    load.labels.push_back(bus->name());
    load.series.push_back(add_signal(parse_signal(text, SourceMark{scenario.file, 0, 0})));
  }
  if (!load.series.empty()) plots_.push_back(std::move(load));
  capture_.tap(world.buses());
}

int CaseCollector::add_signal(const SignalExpr& e) {
  const auto it = std::find(signals_.begin(), signals_.end(), e.text);
  if (it != signals_.end()) return static_cast<int>(it - signals_.begin());
  signals_.push_back(e.text);
  columns_.push_back(recorder_.add(world_.resolve(e), true, false));
  return static_cast<int>(signals_.size() - 1);
}

void CaseCollector::event(sim::Time t, const std::string& text) {
  if (events_.size() >= kMaxEvents) {
    ++events_left_out_;
    return;
  }
  const bool fault = text.rfind("fault: ", 0) == 0;
  events_.push_back({sim::seconds(t), fault ? "fault" : "log", fault ? text.substr(7) : text});
}

CaseRecord CaseCollector::finish(const Verdicts& verdicts, const RunSummary& summary, std::uint64_t seed, int exit_code) const {
  CaseRecord r;
  r.name = scenario_.name;
  r.file = scenario_.file;
  r.exit_code = exit_code;
  r.simulated_s = summary.simulated_s;
  r.wall_s = summary.wall_s;
  r.seed = seed;
  r.interrupted = summary.interrupted;
  const auto& outcomes = verdicts.outcomes();
  // Failures first when there are too many to keep: they are what the page is read for.
  for (const auto& o : outcomes)
    if (!o.passed && r.outcomes.size() < kMaxOutcomes) r.outcomes.push_back(o);
  for (const auto& o : outcomes)
    if (o.passed && r.outcomes.size() < kMaxOutcomes) r.outcomes.push_back(o);
  std::stable_sort(r.outcomes.begin(), r.outcomes.end(), [](const Outcome& a, const Outcome& b) { return a.time < b.time; });
  r.outcomes_left_out = outcomes.size() - r.outcomes.size();

  r.times = recorder_.times();
  r.signals = signals_;
  for (int column : columns_) r.values.push_back(recorder_.series(column));
  r.plots = plots_;

  const auto& buses = world_.buses();
  for (const auto& n : world_.nodes())
    r.nodes.push_back({n.spec->name, buses[static_cast<std::size_t>(n.bus)]->name(), n.node_id});
  for (const auto& c : capture_.frames()) {
    const auto& bus = *buses[c.bus];
    r.frames.push_back({c.time.time_since_epoch().count(), wire_name(bus), c.frame, canopen::decode_frame(c.frame)});
  }
  r.frames_seen = capture_.seen();

  for (const auto& bus : buses) {
    CaseRecord::BusLoad b;
    b.name = bus->name();
    b.wire = wire_name(*bus);
    b.bit_rate = bus->timing_bit_rate();
    const auto& st = bus->stats();
    b.frames = st.frames;
    b.error_frames = st.error_frames;
    b.tx_queue_overflow = st.tx_queue_overflow;
    b.mean_load = bus->mean_load();
    auto traffic = bus->traffic();
    std::stable_sort(traffic.begin(), traffic.end(), [](const sim::IdTraffic& a, const sim::IdTraffic& x) { return a.bits > x.bits; });
    const double bit_s = 1.0 / static_cast<double>(b.bit_rate ? b.bit_rate : 1);
    for (std::size_t i = 0; i < traffic.size() && i < 32; ++i) {
      const auto& t = traffic[i];
      b.ids.push_back({t.id, t.extended, t.frames,
                       summary.simulated_s > 0 ? static_cast<double>(t.bits) * bit_s / summary.simulated_s : 0.0});
    }
    r.buses.push_back(std::move(b));
  }
  r.events = events_;
  r.events_left_out = events_left_out_;
  return r;
}

}  // namespace scenario::report
