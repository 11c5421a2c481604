#include "sim/socketcan_transport.h"

#include <linux/can.h>
#include <linux/can/raw.h>
#include <net/if.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "sim/log.h"

namespace sim {

namespace {

constexpr Duration kLinkCheckPeriod = milliseconds(200);

int open_bound_socket(int ifindex, std::string& error) {
  const int fd = ::socket(PF_CAN, SOCK_RAW | SOCK_NONBLOCK | SOCK_CLOEXEC, CAN_RAW);
  if (fd < 0) {
    error = std::string("cannot open a CAN raw socket: ") + std::strerror(errno) +
            (errno == EAFNOSUPPORT ? " (this kernel has no SocketCAN; use the virtual bus or tools/vcan/vcan-run)" : "");
    return -1;
  }
  sockaddr_can addr{};
  addr.can_family = AF_CAN;
  addr.can_ifindex = ifindex;
  if (::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof(addr)) < 0) {
    error = std::string("cannot bind CAN socket: ") + std::strerror(errno);
    ::close(fd);
    return -1;
  }
  return fd;
}

}  // namespace

bool socketcan_available() {
  const int fd = ::socket(PF_CAN, SOCK_RAW | SOCK_CLOEXEC, CAN_RAW);
  if (fd < 0) return false;
  ::close(fd);
  return true;
}

std::unique_ptr<SocketCanTransport> SocketCanTransport::open(const std::string& iface, std::string& error) {
  if (iface.empty() || iface.size() >= IFNAMSIZ) {
    error = "invalid CAN interface name '" + iface + "'";
    return nullptr;
  }
  const unsigned ifindex = ::if_nametoindex(iface.c_str());
  if (ifindex == 0) {
    error = "CAN interface '" + iface + "' does not exist";
    if (!socketcan_available()) error += " (this kernel has no SocketCAN support)";
    return nullptr;
  }
  std::string why;
  const int fd = open_bound_socket(static_cast<int>(ifindex), why);
  if (fd < 0) {
    error = "CAN interface '" + iface + "': " + why;
    return nullptr;
  }
  return std::unique_ptr<SocketCanTransport>(new SocketCanTransport(iface, fd, static_cast<int>(ifindex)));
}

std::unique_ptr<SocketCanTransport> SocketCanTransport::adopt(std::string name, int fd) {
  return std::unique_ptr<SocketCanTransport>(new SocketCanTransport(std::move(name), fd, -1));
}

SocketCanTransport::SocketCanTransport(std::string iface, int fd, int ifindex)
    : iface_(std::move(iface)), fd_(fd), ifindex_(ifindex) {}

SocketCanTransport::~SocketCanTransport() {
  if (fd_ >= 0) ::close(fd_);
}

bool SocketCanTransport::write_frame(const CanFrame& f) {
  can_frame raw{};
  raw.can_id = f.id | (f.extended ? CAN_EFF_FLAG : 0u) | (f.rtr ? CAN_RTR_FLAG : 0u);
  raw.can_dlc = f.dlc;
  std::memcpy(raw.data, f.data.data(), 8);
  const ssize_t n = ::write(fd_, &raw, sizeof(raw));
  if (n == static_cast<ssize_t>(sizeof(raw))) {
    ++stats_.tx_frames;
    return true;
  }
  if (n < 0 && (errno == ENOBUFS || errno == EAGAIN)) {
    ++stats_.tx_busy;
    return false;
  }
  if (n < 0 && (errno == ENETDOWN || errno == ENODEV || errno == ENXIO)) {
    mark_down(std::strerror(errno));
    return false;
  }
  // Anything else (e.g. EINVAL) cannot succeed on retry: count it as lost.
  ++stats_.tx_dropped;
  return true;
}

void SocketCanTransport::send(const CanFrame& frame) {
  // Keep order: once something waits for retry, later frames queue behind it.
  if (link_up_ && retry_.empty() && write_frame(frame)) return;
  if (retry_.size() >= kRetryCapacity) {
    ++stats_.tx_dropped;
    return;
  }
  retry_.push(frame);
}

bool SocketCanTransport::receive(CanFrame& frame) {
  can_frame raw{};
  for (;;) {
    const ssize_t n = ::read(fd_, &raw, sizeof(raw));
    if (n < 0) {
      if (errno == EINTR) continue;
      if (errno == ENETDOWN || errno == ENODEV) mark_down(std::strerror(errno));
      return false;
    }
    if (n != static_cast<ssize_t>(sizeof(raw))) continue;  // not a classic CAN frame: skip
    if (raw.can_id & CAN_ERR_FLAG) continue;                // error frames are not bus traffic
    if (!link_up_) {
      link_up_ = true;
      log(LogLevel::Warn, "CAN interface '{}' is up again; resuming", iface_);
    }
    frame = CanFrame{};
    frame.extended = (raw.can_id & CAN_EFF_FLAG) != 0;
    frame.rtr = (raw.can_id & CAN_RTR_FLAG) != 0;
    frame.id = raw.can_id & (frame.extended ? CAN_EFF_MASK : CAN_SFF_MASK);
    frame.dlc = raw.can_dlc > 8 ? 8 : raw.can_dlc;
    std::memcpy(frame.data.data(), raw.data, 8);
    ++stats_.rx_frames;
    return true;
  }
}

void SocketCanTransport::mark_down(const char* why) {
  if (!link_up_) return;
  link_up_ = false;
  ++stats_.link_down_events;
  log(LogLevel::Warn, "CAN interface '{}' is down ({}); frames are queued until it returns", iface_, why);
}

bool SocketCanTransport::rebind() {
  const unsigned ifindex = ::if_nametoindex(iface_.c_str());
  if (ifindex == 0) return false;
  if (static_cast<int>(ifindex) == ifindex_) return true;
  // The interface was deleted and re-created: bind a fresh socket to the new index.
  std::string error;
  const int fd = open_bound_socket(static_cast<int>(ifindex), error);
  if (fd < 0) return false;
  ::close(fd_);
  fd_ = fd;
  ifindex_ = static_cast<int>(ifindex);
  return true;
}

void SocketCanTransport::check_link() {
  if (ifindex_ < 0) return;  // adopted socket: no interface to watch
  ifreq ifr{};
  std::strncpy(ifr.ifr_name, iface_.c_str(), IFNAMSIZ - 1);
  const bool exists = ::ioctl(fd_, SIOCGIFFLAGS, &ifr) == 0;
  const bool up = exists && (ifr.ifr_flags & IFF_UP) && rebind();
  if (!up) {
    mark_down(exists ? "link down" : "interface removed");
  } else if (!link_up_) {
    link_up_ = true;
    log(LogLevel::Warn, "CAN interface '{}' is up again; resuming", iface_);
  }
}

void SocketCanTransport::service(Time now) {
  if (now >= next_link_check_) {
    next_link_check_ = now + kLinkCheckPeriod;
    check_link();
  }
  if (!link_up_) {
    // While down, keep only the newest frames: a master that comes back wants current state.
    while (retry_.size() > kRetryCapacity / 4) {
      retry_.pop();
      ++stats_.tx_dropped;
    }
    return;
  }
  while (!retry_.empty()) {
    if (!write_frame(retry_.front())) break;
    retry_.pop();
  }
}

}  // namespace sim
