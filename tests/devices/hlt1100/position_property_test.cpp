// Property test of the HLT 1100 position arithmetic over the bus: for random measuring lengths,
// magnet positions, presets, counting directions, saves and power cycles (seeded, deterministic)
// 6020h:01 always equals the digest's formula (§4.2/§4.3):
//   raw_inc = clamp(round(x / 0.1 mm), 0, N-1); raw = raw_inc or N-1-raw_inc (6000h bit 3)
//   6020h = raw + 650Ah:01 + offset; a preset P sets offset = P - (raw + 650Ah:01)
// and the offset survives a power cycle only if it was saved.
#include <cmath>
#include <random>

#include "tests/devices/hlt1100/hlt1100_fixture.h"

namespace hlt1100::test {
namespace {

struct Model {
  std::int64_t n = 0;
  std::int64_t man_offset = 0;
  std::int64_t offset = 0, saved_offset = 0;
  bool down = false, saved_down = false;
  std::int64_t raw(double x_mm) const {
    const std::int64_t inc = std::clamp<std::int64_t>(std::llround(x_mm * 10.0), 0, n - 1);
    return down ? n - 1 - inc : inc;
  }
  std::int64_t position(double x_mm) const { return raw(x_mm) + man_offset + offset; }
};

class PositionProperty : public ::testing::TestWithParam<int> {};

TEST_P(PositionProperty, OutputEqualsTheFormula) {
  std::mt19937 rng(static_cast<unsigned>(GetParam()));
  std::uniform_real_distribution<double> length(20.0, 3000.0);
  Model m;
  const double length_mm = std::round(length(rng) * 10.0) / 10.0;
  m.n = std::llround(length_mm * 10.0);
  m.man_offset = std::uniform_int_distribution<int>(-500, 500)(rng);
  devices::DeviceOptions o;
  o.node_id = 5;
  o.settings = {{"measuring_length_mm", std::to_string(length_mm)},
                {"manufacturer_offset", std::to_string(m.man_offset)},
                {"save_delay_ms", "20"}};
  const vtest::TempPath store("vplant-hlt1100-property");  // removed also when an assertion fails
  o.store_path = store;
  std::string error;
  auto device = Hlt1100Device::create(o, error);
  ASSERT_TRUE(device) << error;
  vtest::CanopenHarness h(device->node());
  std::uniform_real_distribution<double> where(0.0, length_mm - 0.051);
  double x = where(rng);
  device->set_input("position", x / 1000.0);
  h.power_on();
  std::uniform_int_distribution<int> action(0, 9);
  std::string trace;
  for (int step = 0; step < 60; ++step) {
    const int a = action(rng);
    trace += " " + std::to_string(a);
    switch (a) {
      case 0: {  // preset anywhere in 0..N-1
        const auto p = std::uniform_int_distribution<std::int64_t>(0, m.n - 1)(rng);
        ASSERT_EQ(h.write(0x6010, 1, static_cast<std::uint32_t>(p), 4), 0u);
        m.offset = p - (m.raw(x) + m.man_offset);
        break;
      }
      case 1:
        m.down = !m.down;
        ASSERT_EQ(h.write(0x6000, 0, m.down ? 8 : 0, 2), 0u);
        break;
      case 2:
        ASSERT_EQ(h.write(0x1010, 1, kSave, 4), 0xFFFFFFFFu);  // answered after the silent time
        h.run_ms(25);
        h.take();
        m.saved_offset = m.offset;
        m.saved_down = m.down;
        break;
      case 3:
        device->power_off();
        h.run_ms(3);
        x = where(rng);  // the rod moves while the sensor is off
        device->set_input("position", x / 1000.0);
        h.power_on();
        m.offset = m.saved_offset;
        m.down = m.saved_down;
        break;
      default:
        x = where(rng);
        device->set_input("position", x / 1000.0);
        break;
    }
    h.run_ms(2);
    const auto got = h.read_u(0x6020, 1);
    ASSERT_TRUE(got);
    ASSERT_EQ(static_cast<std::int32_t>(static_cast<std::uint32_t>(*got)), m.position(x))
        << "seed " << GetParam() << " step " << step << " x=" << x << " mm, actions" << trace;
  }
}

INSTANTIATE_TEST_SUITE_P(Seeds, PositionProperty, ::testing::Range(1, 21));

}  // namespace
}  // namespace hlt1100::test
