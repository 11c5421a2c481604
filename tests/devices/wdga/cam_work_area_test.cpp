// WDGA CAM unit (6300h-6337h, one channel, 8 cams with hysteresis) and work area (6400h-6402h),
// including the manual's own CAM example with its 6323h typo (digest checklist 31-34; W15-W18).
#include "tests/devices/wdga/wdga_fixture.h"

namespace wdga::test {
namespace {

class Cam : public WdgaTest {
 protected:
  Cam() {
    EXPECT_EQ(h().write(0x6001, 0, 4096, 4), 0u);
    at(0);
  }
  /// Puts the shaft at `steps` of 4096 per turn (inside the step).
  void at(std::int64_t steps) {
    turn_to((static_cast<double>(steps) + 0.5) / 4096);
    h().run_ms(2);
  }
  std::uint64_t cams() { return u(0x6300, 1); }
};

TEST_F(Cam, TheManualsExample) {
  EXPECT_EQ(sdo({0x23, 0x01, 0x63, 0x01, 0x07, 0x00, 0x00, 0x00}), resp({0x60, 0x01, 0x63, 0x01}));  // 4 bytes to a U8
  EXPECT_EQ(sdo({0x23, 0x20, 0x63, 0x01, 0x00, 0x08, 0x00, 0x00}), resp({0x60, 0x20, 0x63, 0x01}));
  EXPECT_EQ(sdo({0x23, 0x21, 0x63, 0x01, 0xFF, 0x0F, 0x00, 0x00}), resp({0x60, 0x21, 0x63, 0x01}));
  EXPECT_EQ(sdo({0x23, 0x23, 0x63, 0x01, 0xAA, 0x02, 0x00, 0x00}), resp({0x60, 0x23, 0x63, 0x01}));  // 6323h [sic]
  EXPECT_EQ(sdo({0x23, 0x10, 0x63, 0x01, 0x00, 0x00, 0x00, 0x00}), resp({0x60, 0x10, 0x63, 0x01}));
  EXPECT_EQ(sdo({0x23, 0x11, 0x63, 0x01, 0x01, 0x08, 0x00, 0x00}), resp({0x60, 0x11, 0x63, 0x01}));
  EXPECT_EQ(sdo({0x23, 0x12, 0x63, 0x01, 0x00, 0x00, 0x00, 0x00}), resp({0x60, 0x12, 0x63, 0x01}));  // unchanged
  h().run_ms(2);
  EXPECT_EQ(cams(), 0x05u);  // at 0: CAM1 [0, 2048] and CAM3 [0, 0]
  at(100);
  EXPECT_EQ(cams(), 0x01u);
  ASSERT_EQ(h().write(0x6322, 1, 682, 4), 0u);
  h().run_ms(2);
  EXPECT_EQ(cams(), 0x05u);
  at(3000);
  EXPECT_EQ(cams(), 0x02u);
  at(4095);
  EXPECT_EQ(cams(), 0x02u);
  at(4096);  // the next turn: 4096 is above every cam (cams do not wrap)
  EXPECT_EQ(cams(), 0x00u);
}

TEST_F(Cam, LowLimitMustStayBelowHighLimit) {
  ASSERT_EQ(h().write(0x6321, 1, 4095, 4), 0u);
  EXPECT_EQ(sdo({0x23, 0x11, 0x63, 0x01, 0x00, 0x10, 0x00, 0x00}), resp({0x80, 0x11, 0x63, 0x01, 0x36, 0x00, 0x09, 0x06}));
  EXPECT_EQ(h().write(0x6311, 1, 4094, 4), 0u);
  EXPECT_EQ(h().write(0x6321, 1, 10, 4), 0u);  // high limits are not checked
}

TEST_F(Cam, PolarityInvertsAndDisabledCamsReadZero) {
  ASSERT_EQ(h().write(0x6320, 1, 2048, 4), 0u);
  ASSERT_EQ(h().write(0x6301, 1, 0x01, 1), 0u);
  at(100);
  EXPECT_EQ(cams(), 0x01u);
  ASSERT_EQ(h().write(0x6302, 1, 0x01, 1), 0u);
  h().run_ms(2);
  EXPECT_EQ(cams(), 0x00u);
  at(3000);
  EXPECT_EQ(cams(), 0x01u);  // inverted: high outside
  ASSERT_EQ(h().write(0x6302, 1, 0x81, 1), 0u);
  h().run_ms(2);
  EXPECT_EQ(cams(), 0x01u);  // CAM8 inverted but disabled
}

TEST_F(Cam, HysteresisDelaysTheSwitchPointsInTheDirectionOfTravel) {
  ASSERT_EQ(h().write(0x6320, 1, 2048, 4), 0u);
  ASSERT_EQ(h().write(0x6330, 1, 10, 4), 0u);
  ASSERT_EQ(h().write(0x6301, 1, 0x01, 1), 0u);
  std::int64_t off_at = -1;
  for (std::int64_t s = 2040; s <= 2070; ++s) {
    at(s);
    if (cams() == 0 && off_at < 0) off_at = s;
  }
  EXPECT_EQ(off_at, 2059);
  at(2100);
  std::int64_t on_at = -1;
  for (std::int64_t s = 2100; s >= 2040; --s) {
    at(s);
    if (cams() == 1 && on_at < 0) on_at = s;
  }
  EXPECT_EQ(on_at, 2048);
  // Below the low limit the same: once inside it stays inside down to -10.
  ASSERT_EQ(h().write(0x6310, 1, 100, 4), 0u);
  at(150);
  at(95);
  EXPECT_EQ(cams(), 0x01u);
  at(89);
  EXPECT_EQ(cams(), 0x00u);
  at(95);
  EXPECT_EQ(cams(), 0x00u);
}

class WorkArea : public WdgaTest {};

TEST_F(WorkArea, InsideAboveAndBelow) {
  turn_to(20000.5 / 16384);
  h().run_ms(2);
  EXPECT_EQ(sdo({0x40, 0x00, 0x64, 0x01}), resp({0x4F, 0x00, 0x64, 0x01, 0x02}));
  ASSERT_EQ(h().write(0x6003, 0, 100, 4), 0u);
  h().run_ms(2);
  EXPECT_EQ(u(0x6400, 1), 0x00u);
  ASSERT_EQ(h().write(0x6401, 1, 500, 4), 0u);
  h().run_ms(2);
  EXPECT_EQ(u(0x6400, 1), 0x04u);
  EXPECT_EQ(u(0x6400, 0), 1u);
}

}  // namespace
}  // namespace wdga::test
