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
  if (to_wire_.push(frame)) {
    ++stats_.tx_frames;
    wake_io_pending_ = true;
  } else {
    ++stats_.tx_dropped;
  }
}

bool QueuedTransport::receive(CanFrame& frame) {
  if (to_bus_.pop(frame)) {
    ++stats_.rx_frames;
    return true;
  }
  // Clear the wake-up, then look again: a frame queued between the two steps is not missed, and
  // one queued after the drain leaves the fd readable for the next poll.
  drain_fd(to_bus_fd_);
  if (to_bus_.pop(frame)) {
    ++stats_.rx_frames;
    return true;
  }
  return false;
}

void QueuedTransport::service(Time) {
  if (wake_io_pending_) {
    signal_fd(to_io_fd_);
    wake_io_pending_ = false;
  }
  stats_.link_down_events = link_down_.load(std::memory_order_relaxed);
}

void QueuedTransport::clear_io_wake() { drain_fd(to_io_fd_); }

bool QueuedTransport::push_to_bus(const CanFrame& frame) {
  if (to_bus_.push(frame)) return true;
  rx_dropped_.fetch_add(1, std::memory_order_relaxed);
  return false;
}

void QueuedTransport::notify_bus() { signal_fd(to_bus_fd_); }

void QueuedTransport::request_stop() {
  stop_.store(true, std::memory_order_release);
  signal_fd(to_io_fd_);
}

}  // namespace sim
