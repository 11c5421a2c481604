// sim::SocketCanTransport on real SocketCAN vcan interfaces. Registered through
// vplant_add_vcan_test (IFACES vcan0,vcan1), so it runs under tools/vcan/vcan-run: natively where
// the host kernel has vcan, in a qemu guest elsewhere. It never skips: no vcan is a failure.
#include <gtest/gtest.h>
#include <poll.h>

#include <chrono>
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <string>
#include <thread>

#include "sim/socketcan_transport.h"

namespace {

using sim::CanFrame;
using sim::SocketCanTransport;

std::unique_ptr<SocketCanTransport> open_or_fail(const std::string& iface) {
  std::string error;
  auto t = SocketCanTransport::open(iface, error);
  EXPECT_TRUE(t) << "cannot open " << iface << ": " << error
                 << " (run this test through tools/vcan/vcan-run)";
  return t;
}

// Waits up to `timeout` for a frame on `t`.
bool receive_within(SocketCanTransport& t, CanFrame& frame,
                    std::chrono::milliseconds timeout = std::chrono::milliseconds(2000)) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    if (t.receive(frame)) return true;
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return false;
    pollfd pfd{t.wait_fd(), POLLIN, 0};
    ::poll(&pfd, 1, static_cast<int>(left.count()));
  }
}

// Nothing arrives within `quiet`.
bool stays_quiet(SocketCanTransport& t, std::chrono::milliseconds quiet = std::chrono::milliseconds(200)) {
  CanFrame frame;
  return !receive_within(t, frame, quiet);
}

TEST(SocketCanVcan, KernelHasSocketCan) {
  EXPECT_TRUE(sim::socketcan_available()) << "PF_CAN sockets cannot be opened here";
}

TEST(SocketCanVcan, FrameSentOnOneTransportArrivesOnTheOther) {
  auto a = open_or_fail("vcan0");
  auto b = open_or_fail("vcan0");
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->name(), "vcan0");
  EXPECT_TRUE(a->link_up());
  EXPECT_GE(a->wait_fd(), 0);

  const CanFrame sent = CanFrame::data_frame(0x123, {0xDE, 0xAD, 0xBE, 0xEF});
  a->send(sent);
  CanFrame got;
  ASSERT_TRUE(receive_within(*b, got)) << "no frame on the second transport";
  EXPECT_EQ(got, sent) << "got " << sim::to_candump(got);
  EXPECT_EQ(sim::to_candump(got), "123#DEADBEEF");
  EXPECT_TRUE(stays_quiet(*a)) << "a raw socket must not receive its own frame";
  EXPECT_EQ(a->stats().tx_frames, 1u);
  EXPECT_EQ(b->stats().rx_frames, 1u);

  // And back the other way.
  const CanFrame reply = CanFrame::data_frame(0x5A1, {0x01});
  b->send(reply);
  ASSERT_TRUE(receive_within(*a, got));
  EXPECT_EQ(got, reply);
}

TEST(SocketCanVcan, ExtendedRemoteAndEmptyFramesSurvive) {
  auto a = open_or_fail("vcan0");
  auto b = open_or_fail("vcan0");
  ASSERT_TRUE(a && b);
  const CanFrame frames[] = {
      CanFrame::data_frame(0x18FEF100, {1, 2, 3, 4, 5, 6, 7, 8}),
      CanFrame::remote_frame(0x701, 1),
      CanFrame::data_frame(0x000, std::initializer_list<std::uint8_t>{}),
  };
  CanFrame ext = frames[0];
  ASSERT_TRUE(ext.extended) << "0x18FEF100 needs a 29-bit identifier";
  for (const CanFrame& f : frames) a->send(f);
  for (const CanFrame& f : frames) {
    CanFrame got;
    ASSERT_TRUE(receive_within(*b, got)) << "missing " << sim::to_candump(f);
    EXPECT_EQ(got, f) << "sent " << sim::to_candump(f) << ", got " << sim::to_candump(got);
  }
}

TEST(SocketCanVcan, InterfacesAreSeparateBuses) {
  auto on0 = open_or_fail("vcan0");
  auto on1 = open_or_fail("vcan1");
  auto rx1 = open_or_fail("vcan1");
  ASSERT_TRUE(on0 && on1 && rx1);
  on1->send(CanFrame::data_frame(0x321, {0x42}));
  CanFrame got;
  ASSERT_TRUE(receive_within(*rx1, got));
  EXPECT_EQ(sim::to_candump(got), "321#42");
  EXPECT_TRUE(stays_quiet(*on0)) << "a vcan1 frame showed up on vcan0";
}

TEST(SocketCanVcan, ServiceKeepsAnUpLinkUp) {
  auto a = open_or_fail("vcan0");
  ASSERT_TRUE(a);
  a->service(sim::kTimeZero + sim::milliseconds(1000));
  EXPECT_TRUE(a->link_up());
  EXPECT_EQ(a->stats().link_down_events, 0u);
}

TEST(SocketCanVcan, MissingInterfaceIsAnErrorThatNamesIt) {
  std::string error;
  auto t = SocketCanTransport::open("vcannope9", error);
  EXPECT_FALSE(t);
  EXPECT_NE(error.find("vcannope9"), std::string::npos) << error;
  EXPECT_NE(error.find("does not exist"), std::string::npos) << error;
}

}  // namespace
