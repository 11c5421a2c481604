// Property test of the WDGA position arithmetic over the bus (seeded, deterministic): random
// variants, counting directions, scaling on/off, resolutions (MUR), total measuring ranges (not
// powers of two), presets, angle sequences — including turns of up to 2^36 revolutions and
// power cycles during which the shaft keeps turning — and 6004h/6008h always equal the digest's
// formula (§4.1-§4.5), written out here independently of the device code:
//   P = floor(θ·16384) (singleturn: within one turn);  Pd = ±P (singleturn: mod 16384)
//   S = scaling ? floor(Pd·MUR / 16384) : Pd;  R = scaling ? TMR : 16384 (ST) or 2^53 (MT)
//   X = (S + O) mod R with a preset V setting O = V − (S mod R);  6004h = X mod 2^32, 6008h = X.
#include <random>

#include "tests/devices/wdga/wdga_fixture.h"

namespace wdga::test {
namespace {

__extension__ typedef __int128 I128;

I128 fdiv(I128 a, I128 b) {
  I128 q = a / b;
  if (a % b != 0 && (a < 0) != (b < 0)) --q;
  return q;
}
I128 fmod_pos(I128 a, I128 m) { return a - fdiv(a, m) * m; }

struct Model {
  bool multiturn = true, ccw = false, scaling = true;
  std::uint64_t mur = 16384, tmr = 1ull << 30;
  I128 offset = 0;
  struct Saved {
    bool ccw = false, scaling = true;
    std::uint64_t mur = 16384, tmr = 1ull << 30;
    I128 offset = 0;
  } saved;

  std::uint64_t range() const {
    if (scaling) return tmr;
    return multiturn ? 16384ull << 39 : 16384ull;
  }
  I128 s(std::int64_t steps) const {  // steps = floor(θ·16384), unbounded
    I128 p = steps;
    if (!multiturn) p = fmod_pos(p, 16384);
    I128 pd = ccw ? -p : p;
    if (!multiturn) pd = fmod_pos(pd, 16384);
    return scaling ? fdiv(pd * static_cast<I128>(mur), 16384) : pd;
  }
  std::uint64_t x(std::int64_t steps) const {
    return static_cast<std::uint64_t>(fmod_pos(s(steps) + offset, static_cast<I128>(range())));
  }
  void preset(std::uint64_t v, std::int64_t steps) { offset = static_cast<I128>(v) - fmod_pos(s(steps), range()); }
  void save() { saved = {ccw, scaling, mur, tmr, offset}; }
  void power_cycle() {
    ccw = saved.ccw;
    scaling = saved.scaling;
    mur = saved.mur;
    tmr = saved.tmr;
    offset = saved.offset;
  }
};

class WdgaPositionProperty : public ::testing::TestWithParam<int> {};

TEST_P(WdgaPositionProperty, OutputEqualsTheFormula) {
  std::mt19937_64 rng(static_cast<std::uint64_t>(GetParam()) * 7919);
  const bool multiturn = GetParam() % 3 != 0;
  devices::DeviceOptions o;
  o.variant = multiturn ? "multiturn" : "singleturn";
  const vtest::TempPath store("vplant-wdga-property");  // removed also when an assertion fails
  o.store_path = store;
  std::string error;
  auto device = WdgaDevice::create(o, error);
  ASSERT_TRUE(device) << error;
  vtest::CanopenHarness h(device->node());
  Model m;
  m.multiturn = multiturn;
  m.tmr = multiturn ? (1ull << 30) : 16384;
  m.save();
  auto set_steps = [&](std::int64_t steps) {
    device->set_input("angle", (static_cast<double>(steps) + 0.5) / 16384.0 * 2 * std::numbers::pi);
  };
  std::int64_t steps = std::uniform_int_distribution<std::int64_t>(-1000000, 1000000)(rng);
  set_steps(steps);
  auto boot = [&] {
    device->power_on(h.now());
    h.run_ticks(1);
    h.send(vtest::Frame(0x080, std::vector<std::uint8_t>{}));
    h.run_ticks(1);
  };
  boot();
  auto rnd = [&](std::uint64_t lo, std::uint64_t hi) { return std::uniform_int_distribution<std::uint64_t>(lo, hi)(rng); };
  std::string trace;
  for (int step = 0; step < 80; ++step) {
    const int action = static_cast<int>(rnd(0, 11));
    trace += " " + std::to_string(action);
    switch (action) {
      case 0: {  // operating parameters: direction and scaling
        m.ccw = rnd(0, 1);
        m.scaling = rnd(0, 3) != 0;
        ASSERT_EQ(h.write(0x6000, 0, (m.ccw ? 1u : 0u) | (m.scaling ? 4u : 0u), 2), 0u);
        m.offset = 0;  // [R, A-24]
        break;
      }
      case 1: {
        m.mur = rnd(0, 3) == 0 ? 16384 : rnd(1, 16384);
        ASSERT_EQ(h.write(0x6001, 0, static_cast<std::uint32_t>(m.mur), 4), 0u);
        m.offset = 0;
        if (!multiturn && m.tmr > m.mur) {  // keep the singleturn range within one turn
          m.tmr = m.mur;
          ASSERT_EQ(h.write(0x6002, 0, static_cast<std::uint32_t>(m.tmr), 4), 0u);
        }
        break;
      }
      case 2: {
        m.tmr = multiturn ? rnd(1, 0xFFFFFFFF) : rnd(1, m.mur);
        ASSERT_EQ(h.write(0x6002, 0, static_cast<std::uint32_t>(m.tmr), 4), 0u);
        m.offset = 0;
        break;
      }
      case 3: {  // preset (32 or 64 bit)
        const std::uint64_t v = rnd(0, std::min<std::uint64_t>(m.range(), 1ull << 40) - 1);
        if (v <= 0xFFFFFFFF && rnd(0, 1)) {
          ASSERT_EQ(h.write(0x6003, 0, static_cast<std::uint32_t>(v), 4), 0u);
        } else {
          std::vector<std::uint8_t> bytes(8);
          for (int i = 0; i < 8; ++i) bytes[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(v >> (8 * i));
          ASSERT_EQ(h.download(0x6009, 0, bytes), 0u);
        }
        m.preset(v, steps);
        break;
      }
      case 4:
        ASSERT_EQ(h.write(0x1010, 1, kSave, 4), 0u);
        m.save();
        break;
      case 5: {  // power cycle; the shaft turns while the node is off
        device->power_off();
        h.run_ms(2);
        steps += static_cast<std::int64_t>(rnd(0, 1ull << 20)) - (1 << 19);
        set_steps(steps);
        boot();
        m.power_cycle();
        break;
      }
      case 6:  // a huge multiturn excursion (up to 2^36 turns)
        steps += (static_cast<std::int64_t>(rnd(0, 1ull << 36)) - (1ll << 35)) * 16384;
        set_steps(steps);
        break;
      default:  // small moves, across the wrap
        steps += static_cast<std::int64_t>(rnd(0, 40000)) - 20000;
        set_steps(steps);
        break;
    }
    h.run_ms(2);
    const auto p32 = h.read_u(0x6004, 0);
    const auto p64 = h.read_u(0x6008, 0);
    ASSERT_TRUE(p32 && p64);
    const std::uint64_t want = m.x(steps);
    ASSERT_EQ(*p64, want) << "seed " << GetParam() << " step " << step << " actions" << trace;
    ASSERT_EQ(*p32, want & 0xFFFFFFFFu) << "seed " << GetParam() << " step " << step;
  }
}

INSTANTIATE_TEST_SUITE_P(Seeds, WdgaPositionProperty, ::testing::Range(1, 31));

}  // namespace
}  // namespace wdga::test
