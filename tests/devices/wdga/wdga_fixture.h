// A WDGA (factory node-ID 127, multiturn unless told otherwise) on a virtual bus with a scripted
// master; boot() powers it on and ends the automatic bit-rate detection with a SYNC.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <numbers>
#include <string>

#include "devices/canopen/lss_slave.h"
#include "devices/wdga/wdga_device.h"
#include "devices/wdga/wdga_object_dictionary.h"
#include "tests/support/temp_path.h"
#include "tests/support/canopen_harness.h"

namespace wdga::test {

using vtest::Frame;
using vtest::Frames;

inline std::vector<std::uint8_t> eight(std::initializer_list<std::uint8_t> bytes) {
  std::vector<std::uint8_t> d(bytes);
  d.resize(8, 0);
  return d;
}

constexpr std::uint32_t kSave = 0x65766173, kLoad = 0x64616F6C;

class WdgaTest : public ::testing::Test {
 protected:
  explicit WdgaTest(std::map<std::string, std::string> settings = {}, std::string variant = "", bool boot_now = true) {
    devices::DeviceOptions o;
    o.variant = std::move(variant);
    o.settings = std::move(settings);
    o.store_path = store_path_;
    std::string error;
    device_ = WdgaDevice::create(o, error);
    EXPECT_TRUE(device_) << error;
    h_ = std::make_unique<vtest::CanopenHarness>(device_->node());
    if (boot_now) boot();
  }

  /// Power-on, bit-rate detection by one SYNC (as in the manual's quick start), boot-up taken.
  void boot() {
    device_->power_on(h().now());
    h().run_ticks(1);
    h().send(Frame(0x080, eight({})));
    h().run_ticks(1);
    h().take();
  }
  void power_cycle() {
    device_->power_off();
    h().run_ms(10);
    boot();
  }
  vtest::CanopenHarness& h() { return *h_; }
  WdgaDevice& device() { return *device_; }
  canopen::ObjectDictionary& od() { return device_->node().od(); }
  std::uint8_t id() { return device_->node().node_id(); }
  /// Sets the shaft angle in revolutions (clockwise positive).
  void turn_to(double revolutions) { device_->set_input("angle", revolutions * 2 * std::numbers::pi); }
  void start() {
    h().nmt(0x01, 0);
    h().run_ticks(1);
  }
  std::optional<Frame> sdo(std::initializer_list<std::uint8_t> request) { return h().sdo(request); }
  std::uint32_t abort_of_read(std::uint16_t index, std::uint8_t sub) {
    std::uint32_t code = 0;
    EXPECT_FALSE(h().upload(index, sub, &code));
    return code;
  }
  std::uint64_t u(std::uint16_t index, std::uint8_t sub = 0) {
    const auto v = h().read_u(index, sub);
    EXPECT_TRUE(v) << std::hex << index << ":" << int(sub);
    return v.value_or(0xDEADBEEF);
  }
  std::int64_t i16(std::uint16_t index, std::uint8_t sub) { return static_cast<std::int16_t>(u(index, sub)); }
  Frame emcy(std::initializer_list<std::uint8_t> bytes) { return Frame(0x80u + id(), eight(bytes)); }
  Frame resp(std::initializer_list<std::uint8_t> bytes) { return Frame(0x580u + id(), eight(bytes)); }

  vtest::TempPath store_path_{"vplant-wdga-test"};  // removed with the fixture
  std::unique_ptr<WdgaDevice> device_;
  std::unique_ptr<vtest::CanopenHarness> h_;
};

}  // namespace wdga::test
