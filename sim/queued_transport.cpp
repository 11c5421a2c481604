#include "sim/queued_transport.h"

#include <sys/eventfd.h>
#include <unistd.h>

namespace sim {

namespace {
void signal_fd(int fd) {
  const std::uint64_t one = 1;
  // A full counter (never in practice) still leaves the fd readable, which is all that matters.
  [[maybe_unused]] const auto n = ::write(fd, &one, sizeof one);
}
void drain_fd(int fd) {
  std::uint64_t value = 0;
  [[maybe_unused]] const auto n = ::read(fd, &value, sizeof value);
}
}  // namespace

QueuedTransport::QueuedTransport(std::string name)
    : name_(std::move(name)),
      to_bus_fd_(::eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC)),
      to_io_fd_(::eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC)) {}

QueuedTransport::~QueuedTransport() {
  if (to_bus_fd_ >= 0) ::close(to_bus_fd_);
  if (to_io_fd_ >= 0) ::close(to_io_fd_);
}

void QueuedTransport::send(const CanFrame& frame) {
  // The last kResultReserve slots are kept for wire results (see kResultReserve).
  if (to_wire_.free_slots() > kResultReserve && to_wire_.push(WireEvent{WireEvent::Kind::Frame, 0, frame})) {
    ++stats_.tx_frames;
    wake_io_pending_ = true;
  } else {
    ++stats_.tx_dropped;
  }
}

void QueuedTransport::wire_result(std::uint32_t tag, const CanFrame& frame, WireResult result) {
  const auto kind = result == WireResult::Delivered ? WireEvent::Kind::Delivered
                    : result == WireResult::Refused ? WireEvent::Kind::Refused
                                                    : WireEvent::Kind::Lost;
  if (to_wire_.push(WireEvent{kind, tag, frame})) wake_io_pending_ = true;
}

bool QueuedTransport::receive(CanFrame& frame) {
  std::uint32_t tag = 0;
  return receive_tagged(frame, tag);
}

bool QueuedTransport::receive_tagged(CanFrame& frame, std::uint32_t& tag) {
  TaggedFrame t;
  if (!to_bus_.pop(t)) {
    // Clear the wake-up, then look again: a frame queued between the two steps is not missed, and
    // one queued after the drain leaves the fd readable for the next poll.
    drain_fd(to_bus_fd_);
    if (!to_bus_.pop(t)) return false;
  }
  ++stats_.rx_frames;
  frame = t.frame;
  tag = t.tag;
  return true;
}

void QueuedTransport::service(Time) {
  if (wake_io_pending_) {
    signal_fd(to_io_fd_);
    wake_io_pending_ = false;
  }
  stats_.link_down_events = link_down_.load(std::memory_order_relaxed);
}

void QueuedTransport::clear_io_wake() { drain_fd(to_io_fd_); }

bool QueuedTransport::push_to_bus(const CanFrame& frame, std::uint32_t tag) {
  if (to_bus_.push(TaggedFrame{frame, tag})) return true;
  rx_dropped_.fetch_add(1, std::memory_order_relaxed);
  return false;
}

void QueuedTransport::notify_bus() { signal_fd(to_bus_fd_); }

void QueuedTransport::request_stop() {
  stop_.store(true, std::memory_order_release);
  signal_fd(to_io_fd_);
}

}  // namespace sim
