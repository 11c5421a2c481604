#include "engine/recorder.h"

#include <cerrno>
#include <cstring>

namespace scenario {

Recorder::~Recorder() { close(); }

int Recorder::add(const Signal& signal, bool keep, bool csv) {
  for (std::size_t i = 0; i < signals_.size(); ++i) {
    if (signals_[i].name() == signal.name()) {
      if (keep) keep_[i] = true;
      if (csv) in_csv_[i] = true;
      any_kept_ |= keep;
      return static_cast<int>(i);
    }
  }
  signals_.push_back(signal);
  keep_.push_back(keep);
  in_csv_.push_back(csv);
  kept_.emplace_back();
  any_kept_ |= keep;
  return static_cast<int>(signals_.size()) - 1;
}

std::string Recorder::open_csv(const std::string& path) {
  csv_ = std::fopen(path.c_str(), "w");
  if (!csv_) return "cannot write '" + path + "': " + std::strerror(errno);
  buffer_.resize(1 << 16);
  std::setvbuf(csv_, buffer_.data(), _IOFBF, buffer_.size());
  std::fputs("time_s", csv_);
  for (std::size_t i = 0; i < signals_.size(); ++i) {
    if (!in_csv_[i]) continue;
    const auto& s = signals_[i];
    // Quote names with commas or quotes (frame expressions may contain them).
    if (s.name().find_first_of(",\"") != std::string::npos) {
      std::string q = "\"";
      for (char c : s.name()) q += c == '"' ? std::string("\"\"") : std::string(1, c);
      std::fprintf(csv_, ",%s\"", q.c_str());
    } else {
      std::fprintf(csv_, ",%s", s.name().c_str());
    }
  }
  std::fputc('\n', csv_);
  return {};
}

void Recorder::step(sim::Time now, sim::Duration) {
  if (now < next_ || signals_.empty()) return;
  next_ = now + period_;
  const double t = sim::seconds(now);
  if (any_kept_) times_.push_back(t);
  if (csv_) std::fprintf(csv_, "%.6f", t);
  for (std::size_t i = 0; i < signals_.size(); ++i) {
    const double v = signals_[i].value();
    if (csv_ && in_csv_[i]) std::fprintf(csv_, ",%.9g", v);
    if (keep_[i]) kept_[i].push_back(v);
  }
  if (csv_) std::fputc('\n', csv_);
  ++rows_;
}

void Recorder::close() {
  if (csv_) {
    std::fclose(csv_);
    csv_ = nullptr;
  }
}

}  // namespace scenario
