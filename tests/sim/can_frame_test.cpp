#include "sim/can_frame.h"

#include <gtest/gtest.h>

using sim::CanFrame;

TEST(CanFrame, FormatsLikeCandump) {
  EXPECT_EQ(sim::to_candump(CanFrame::data_frame(0x601, {0x40, 0x18, 0x10, 0x01, 0, 0, 0, 0})), "601#4018100100000000");
  EXPECT_EQ(sim::to_candump(CanFrame::data_frame(0x705, {0x00})), "705#00");
  EXPECT_EQ(sim::to_candump(CanFrame::data_frame(0x080, {})), "080#");
  EXPECT_EQ(sim::to_candump(CanFrame::remote_frame(0x705, 1)), "705#R1");
  EXPECT_EQ(sim::to_candump(CanFrame::remote_frame(0x705, 0)), "705#R");
  EXPECT_EQ(sim::to_candump(CanFrame::data_frame(0x12345678, {0xAB})), "12345678#AB");
}

TEST(CanFrame, ParsesWhatItFormats) {
  for (const char* text : {"601#4018100100000000", "705#00", "080#", "705#R1", "705#R", "12345678#AB"}) {
    const auto f = sim::parse_candump(text);
    ASSERT_TRUE(f) << text;
    EXPECT_EQ(sim::to_candump(*f), text);
  }
  const auto dotted = sim::parse_candump("123#11.22.33");
  ASSERT_TRUE(dotted);
  EXPECT_EQ(dotted->dlc, 3);
}

TEST(CanFrame, RejectsMalformedText) {
  for (const char* text : {"", "#00", "6011#00", "601#0", "601#GG", "601#001122334455667788", "800#00", "705#R9", "601"}) {
    EXPECT_FALSE(sim::parse_candump(text)) << text;
  }
}

TEST(CanFrame, EqualityIgnoresBytesBeyondDlcAndRtrData) {
  auto a = CanFrame::data_frame(0x181, {1, 2});
  auto b = a;
  b.data[5] = 9;
  EXPECT_EQ(a, b);
  b.data[1] = 3;
  EXPECT_FALSE(a == b);
}
