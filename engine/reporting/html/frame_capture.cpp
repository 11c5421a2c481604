#include "engine/reporting/html/frame_capture.h"

namespace scenario::report {

FrameCapture::FrameCapture() {
  head_.reserve(kHead);
  tail_.resize(kTail);
}

void FrameCapture::tap(const std::vector<std::unique_ptr<sim::Bus>>& buses) {
  for (std::size_t b = 0; b < buses.size(); ++b) {
    taps_.push_back(std::make_unique<BusTap>(*this, static_cast<std::uint16_t>(b)));
    buses[b]->add_tap(taps_.back().get());
  }
}

void FrameCapture::add(std::uint16_t bus, const sim::CanFrame& frame, sim::Time now) {
  const Captured c{now, bus, frame};
  if (head_.size() < kHead) {
    head_.push_back(c);
  } else {
    tail_[(seen_ - kHead) % kTail] = c;
  }
  ++seen_;
}

std::vector<FrameCapture::Captured> FrameCapture::frames() const {
  std::vector<Captured> out(head_);
  if (seen_ <= kHead) return out;
  const std::uint64_t in_tail = seen_ - kHead;
  const std::uint64_t kept = in_tail < kTail ? in_tail : kTail;
  for (std::uint64_t i = in_tail - kept; i < in_tail; ++i) out.push_back(tail_[i % kTail]);
  return out;
}

}  // namespace scenario::report
