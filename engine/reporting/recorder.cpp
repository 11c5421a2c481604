#include "engine/reporting/recorder.h"

#include <cerrno>
#include <cstring>

namespace scenario {

Recorder::~Recorder() { close(); }

int Recorder::add(const Signal& signal, bool keep, bool csv) {
  std::size_t i = 0;
  while (i < signals_.size() && signals_[i].name() != signal.name()) ++i;
  if (i == signals_.size()) {
    signals_.push_back(signal);
    keep_.push_back(false);
    in_csv_.push_back(false);
    kept_index_.push_back(-1);
  }
  if (csv) in_csv_[i] = true;
  if (keep && !keep_[i]) {
    keep_[i] = true;
    kept_index_[i] = static_cast<int>(kept_row_.size());
    kept_row_.push_back(0.0);
    plot_.reserve(kept_row_.size());
  }
  return static_cast<int>(i);
}

void Recorder::fail(int err) {
  if (error_.empty()) error_ = "cannot write '" + csv_path_ + "': " + std::strerror(err != 0 ? err : EIO);
}

std::string Recorder::open_csv(const std::string& path) {
  csv_path_ = path;
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
  errno = 0;
  if (std::fputc('\n', csv_) == EOF) fail(errno);
  return {};
}

void Recorder::step(sim::Time now, sim::Duration) {
  if (now < next_ || signals_.empty()) return;
  next_ = now + period_;
  const double t = sim::seconds(now);
  // A failed write (disk full, EIO) shows as a negative return once the buffer goes to the file;
  // from then on rows are not written, and close() reports it.
  bool write = csv_ != nullptr && error_.empty();
  errno = 0;
  if (write && std::fprintf(csv_, "%.6f", t) < 0) write = false;
  for (std::size_t i = 0; i < signals_.size(); ++i) {
    const double v = signals_[i].value();
    if (write && in_csv_[i] && std::fprintf(csv_, ",%.9g", v) < 0) write = false;
    if (keep_[i]) kept_row_[static_cast<std::size_t>(kept_index_[i])] = v;
  }
  if (write && std::fputc('\n', csv_) == EOF) write = false;
  if (csv_ && error_.empty() && !write) fail(errno);
  if (!kept_row_.empty()) plot_.add(t, kept_row_.data());
  ++rows_;
}

std::vector<double> Recorder::series(int column) const {
  return plot_.series(static_cast<std::size_t>(kept_index_[static_cast<std::size_t>(column)]));
}

std::string Recorder::close() {
  if (csv_) {
    errno = 0;
    if (std::fflush(csv_) != 0 || std::ferror(csv_)) fail(errno);
    errno = 0;
    if (std::fclose(csv_) != 0) fail(errno);
    csv_ = nullptr;
  }
  return error_;
}

}  // namespace scenario
