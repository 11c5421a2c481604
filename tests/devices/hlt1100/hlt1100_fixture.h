// An HLT 1100 (node 5, 500 mm, magnet at 100.0 mm) on a virtual bus with a scripted master.
#pragma once

#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <unistd.h>

#include "devices/canopen/lss_slave.h"
#include "devices/hlt1100/hlt1100_device.h"
#include "devices/hlt1100/hlt1100_object_dictionary.h"
#include "tests/support/temp_path.h"
#include "tests/support/canopen_harness.h"

namespace hlt1100::test {

using vtest::Frame;
using vtest::Frames;

/// Pads to 8 bytes (SDO and LSS frames always have DLC 8).
inline std::vector<std::uint8_t> eight(std::initializer_list<std::uint8_t> bytes) {
  std::vector<std::uint8_t> d(bytes);
  d.resize(8, 0);
  return d;
}

class Hlt1100Test : public ::testing::Test {
 protected:
  explicit Hlt1100Test(std::map<std::string, std::string> settings = {}, std::uint8_t node_id = 5,
                       bool power = true) {
    devices::DeviceOptions o;
    o.node_id = node_id;
    o.settings = std::move(settings);
    o.store_path = store_path_;
    std::string error;
    device_ = Hlt1100Device::create(o, error);
    EXPECT_TRUE(device_) << error;
    h_ = std::make_unique<vtest::CanopenHarness>(device_->node());
    magnet_mm(100.0);
    if (power) {
      h().power_on();
      h().take();
    }
  }

  vtest::CanopenHarness& h() { return *h_; }
  Hlt1100Device& device() { return *device_; }
  canopen::ObjectDictionary& od() { return device_->node().od(); }
  void magnet_mm(double mm) { device_->set_input("position", mm / 1000.0); }
  void power_cycle() {
    device_->power_off();
    h().run_ms(10);
    h().power_on();
  }
  /// NMT start, then the master's view of what followed (one-shot TPDO1).
  Frames start() {
    h().nmt(0x01, 5);
    h().run_ticks(1);
    return h().take();
  }
  std::optional<Frame> sdo(std::initializer_list<std::uint8_t> request) { return h().sdo(request); }
  std::uint32_t abort_of_read(std::uint16_t index, std::uint8_t sub) {
    std::uint32_t code = 0;
    EXPECT_FALSE(h().read(index, sub, &code));
    return code;
  }
  std::int64_t read_i32(std::uint16_t index, std::uint8_t sub) {
    const auto v = h().read_u(index, sub);
    EXPECT_TRUE(v);
    return v ? static_cast<std::int32_t>(static_cast<std::uint32_t>(*v)) : 0;
  }
  std::int64_t read_i16(std::uint16_t index, std::uint8_t sub) {
    const auto v = h().read_u(index, sub);
    EXPECT_TRUE(v);
    return v ? static_cast<std::int16_t>(static_cast<std::uint16_t>(*v)) : 0;
  }
  static Frame emcy(std::initializer_list<std::uint8_t> bytes) { return Frame(0x85, eight(bytes)); }

  vtest::TempPath store_path_{"vplant-hlt1100-test"};  // removed with the fixture
  std::unique_ptr<Hlt1100Device> device_;
  std::unique_ptr<vtest::CanopenHarness> h_;
};

constexpr std::uint32_t kSave = 0x65766173, kLoad = 0x64616F6C;

}  // namespace hlt1100::test
