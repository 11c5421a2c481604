// What the HTML report shows of one case (one scenario run, or one combination of a sweep): the
// verdicts, the recorded signals and the plots over them, a bounded sample of the decoded trace,
// the load of each bus and the run's events (faults injected, script log lines). Plain data: the
// runner's CaseCollector fills it, report_writer.h writes it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "devices/canopen/frame_decoder.h"
#include "engine/running/outcome.h"
#include "sim/can_frame.h"

namespace scenario::report {

struct CaseRecord {
  std::string name;  ///< the case's name (the scenario's, or a sweep combination's)
  std::string file;  ///< the scenario file
  int exit_code = 0;  ///< as `vplant run`: 0 passed, 1 an assertion failed, 2 error
  std::string error;  ///< exit code 2: why (e.g. an output that could not be written)
  double simulated_s = 0;
  double wall_s = 0;
  std::uint64_t seed = 0;
  bool interrupted = false;

  std::vector<Outcome> outcomes;
  std::size_t outcomes_left_out = 0;

  struct Node {
    std::string name, bus;
    int node_id = 0;
  };
  std::vector<Node> nodes;  ///< the trace's node filter

  /// Signals sampled on one time axis (decimated: at most PlotSamples::kMaxPoints per series).
  std::vector<double> times;
  std::vector<std::string> signals;
  std::vector<std::vector<double>> values;  ///< values[signal][sample]; NaN = no value
  struct Plot {
    std::string title, y_label;
    std::vector<std::string> labels;
    std::vector<int> series;  ///< index into `signals`, one per label
  };
  std::vector<Plot> plots;

  struct Frame {
    std::int64_t t_us = 0;
    std::string bus;  ///< the wire name (interface, else bus name)
    sim::CanFrame frame;
    canopen::DecodedFrame decoded;
  };
  std::vector<Frame> frames;       ///< a sample: see FrameCapture
  std::uint64_t frames_seen = 0;  ///< every frame of the run

  struct IdLoad {
    std::uint32_t id = 0;
    bool extended = false;
    std::uint64_t frames = 0;
    double load = 0;  ///< fraction of the run's time
  };
  struct BusLoad {
    std::string name, wire;
    std::uint32_t bit_rate = 0;
    std::uint64_t frames = 0, error_frames = 0, tx_queue_overflow = 0;
    double mean_load = 0;
    std::vector<IdLoad> ids;  ///< the identifiers that occupied the bus most, highest first
  };
  std::vector<BusLoad> buses;

  struct Event {
    double t = 0;
    std::string kind;  ///< "fault" or "log"
    std::string text;
  };
  std::vector<Event> events;
  std::size_t events_left_out = 0;
};

}  // namespace scenario::report
