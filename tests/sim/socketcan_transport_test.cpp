// The transport's transmit path without a CAN interface: a non-blocking socketpair whose buffer
// fills up stands in for a full CAN transmit queue (the kernel answers EAGAIN/ENOBUFS alike).
#include "sim/socketcan_transport.h"

#include <gtest/gtest.h>
#include <linux/can.h>
#include <sys/socket.h>
#include <unistd.h>

namespace {

struct Pair {
  int a = -1, b = -1;
  Pair() {
    int fds[2];
    EXPECT_EQ(socketpair(AF_UNIX, SOCK_SEQPACKET | SOCK_NONBLOCK, 0, fds), 0);
    a = fds[0];
    b = fds[1];
    int small = 4096;  // a few frames only
    setsockopt(a, SOL_SOCKET, SO_SNDBUF, &small, sizeof small);
    setsockopt(b, SOL_SOCKET, SO_RCVBUF, &small, sizeof small);
  }
  ~Pair() {
    if (b >= 0) close(b);
  }
};

std::uint32_t read_id(int fd) {
  can_frame raw{};
  if (read(fd, &raw, sizeof raw) != sizeof raw) return 0xFFFFFFFF;
  return raw.can_id;
}

}  // namespace

TEST(SocketCanTransport, FullTransmitQueueIsCountedRetriedInOrderAndNeverBlocks) {
  Pair p;
  auto t = sim::SocketCanTransport::adopt("pair0", p.a);
  // Far more frames than the buffer holds: send() must return at once every time.
  const int n = 2000;
  for (int i = 0; i < n; ++i) t->send(sim::CanFrame::data_frame(static_cast<std::uint32_t>(i % 0x7FF), {1, 2, 3}));
  EXPECT_GT(t->stats().tx_busy, 0u);
  EXPECT_EQ(t->stats().tx_dropped, 0u);
  EXPECT_LT(t->stats().tx_frames, static_cast<std::uint64_t>(n));
  // Drain the peer and let service() retry; every frame arrives exactly once, in order.
  int received = 0;
  sim::Time now{};
  for (int round = 0; round < 10000 && received < n; ++round) {
    std::uint32_t id;
    while ((id = read_id(p.b)) != 0xFFFFFFFF) {
      ASSERT_EQ(id, static_cast<std::uint32_t>(received % 0x7FF));
      ++received;
    }
    now += sim::milliseconds(1);
    t->service(now);
  }
  EXPECT_EQ(received, n);
  EXPECT_EQ(t->stats().tx_frames, static_cast<std::uint64_t>(n));
}

TEST(SocketCanTransport, RetryQueueOverflowDropsAndCounts) {
  Pair p;
  auto t = sim::SocketCanTransport::adopt("pair0", p.a);
  const std::size_t n = sim::SocketCanTransport::kRetryCapacity + 500;
  for (std::size_t i = 0; i < n; ++i) t->send(sim::CanFrame::data_frame(0x100, {}));
  EXPECT_GT(t->stats().tx_dropped, 0u);
  EXPECT_EQ(t->stats().tx_frames + t->stats().tx_dropped + sim::SocketCanTransport::kRetryCapacity, n);
}

TEST(SocketCanTransport, ReceivesFramesAndSkipsErrorFrames) {
  Pair p;
  auto t = sim::SocketCanTransport::adopt("pair0", p.a);
  can_frame err{};
  err.can_id = CAN_ERR_FLAG | 0x40;
  err.can_dlc = 8;
  ASSERT_EQ(write(p.b, &err, sizeof err), static_cast<ssize_t>(sizeof err));
  can_frame ok{};
  ok.can_id = 0x705;
  ok.can_dlc = 1;
  ASSERT_EQ(write(p.b, &ok, sizeof ok), static_cast<ssize_t>(sizeof ok));
  can_frame rtr{};
  rtr.can_id = 0x123 | CAN_RTR_FLAG;
  rtr.can_dlc = 4;
  ASSERT_EQ(write(p.b, &rtr, sizeof rtr), static_cast<ssize_t>(sizeof rtr));
  sim::CanFrame f;
  ASSERT_TRUE(t->receive(f));
  EXPECT_EQ(sim::to_candump(f), "705#00");
  ASSERT_TRUE(t->receive(f));
  EXPECT_EQ(sim::to_candump(f), "123#R4");
  EXPECT_FALSE(t->receive(f));
}

TEST(SocketCanTransport, MissingInterfaceIsNamed) {
  std::string error;
  EXPECT_EQ(sim::SocketCanTransport::open("nosuchcan7", error), nullptr);
  EXPECT_NE(error.find("'nosuchcan7'"), std::string::npos) << error;
}
