#include "sim/trace_writer.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>

TEST(TraceWriter, WritesCandumpLogLines) {
  char path[] = "/tmp/vplant-trace-XXXXXX";
  const int fd = mkstemp(path);
  ASSERT_GE(fd, 0);
  close(fd);
  {
    std::string error;
    sim::TraceWriter w(path, error);
    ASSERT_TRUE(w.is_open()) << error;
    sim::Bus bus("vcan0");
    struct Nop : sim::FrameReceiver {
      void on_frame(const sim::CanFrame&, sim::Time) override {}
    } a, b;
    const int ea = bus.attach(&a);
    bus.attach(&b);
    bus.add_tap(&w);
    const sim::Time t = sim::Time{} + sim::microseconds(1000250);
    bus.send(ea, sim::CanFrame::data_frame(0x601, {0x40, 0x18, 0x10, 0x01, 0, 0, 0, 0}), t);
    bus.send(ea, sim::CanFrame::remote_frame(0x705, 1), t);
    bus.deliver(t);
  }
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  EXPECT_EQ(ss.str(),
            "(0000000001.000250) vcan0 601#4018100100000000\n"
            "(0000000001.000250) vcan0 705#R1\n");
  std::remove(path);
}

TEST(TraceWriter, ReportsUnwritablePath) {
  std::string error;
  sim::TraceWriter w("/nonexistent-dir/x.log", error);
  EXPECT_FALSE(w.is_open());
  EXPECT_NE(error.find("/nonexistent-dir/x.log"), std::string::npos);
}

// A full disk loses lines: close() says so with the path and the reason instead of success.
TEST(TraceWriter, ReportsWriteFailureOnAFullDevice) {
  std::string error;
  sim::TraceWriter w("/dev/full", error);
  ASSERT_TRUE(w.is_open()) << error;
  sim::Bus bus("vcan0");
  struct Nop : sim::FrameReceiver {
    void on_frame(const sim::CanFrame&, sim::Time) override {}
  } a, b;
  const int ea = bus.attach(&a);
  bus.attach(&b);
  bus.add_tap(&w);
  for (int i = 0; i < 10; ++i) {
    bus.send(ea, sim::CanFrame::data_frame(0x181, {1, 2, 3, 4}), sim::Time{});
    bus.deliver(sim::Time{});
  }
  EXPECT_TRUE(w.error().empty());  // still in the buffer
  EXPECT_FALSE(w.flush());
  EXPECT_EQ(w.close(), "cannot write trace '/dev/full': No space left on device");
  EXPECT_EQ(w.close(), "cannot write trace '/dev/full': No space left on device");  // stays reported
}

TEST(TraceWriter, CloseOfAGoodFileReportsNothing) {
  char path[] = "/tmp/vplant-trace-XXXXXX";
  const int fd = mkstemp(path);
  ASSERT_GE(fd, 0);
  close(fd);
  std::string error;
  sim::TraceWriter w(path, error);
  ASSERT_TRUE(w.is_open()) << error;
  EXPECT_TRUE(w.flush());
  EXPECT_EQ(w.close(), "");
  std::remove(path);
}
