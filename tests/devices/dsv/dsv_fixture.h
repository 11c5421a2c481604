// An emulated DSV on the frame-level test harness, virtual time. Default set-up = the digest's
// checklist preconditions: amplifier, 2 solenoids, 24 V, node 1, stored 604Fh = 0, 6043h = 1,
// 2042h = 2, ramp type 0, enable input 1.
#pragma once

#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "devices/dsv/dsv_device.h"
#include "tests/support/canopen_harness.h"
#include "tests/support/temp_path.h"

namespace dsvtest {

using vtest::Frame;
using vtest::Frames;

inline std::map<std::string, std::string> bus_mode(std::map<std::string, std::string> extra = {}) {
  std::map<std::string, std::string> s = {{"device_local", "0"}, {"control_mode", "1"}, {"mode_of_operation", "2"}};
  for (auto& [k, v] : extra) s[k] = v;
  return s;
}

/// A store file removed when the test program exits (ctest runs each case as its own process).
inline std::string temp_store(const std::string& name) {
  static std::vector<std::unique_ptr<vtest::TempPath>> paths;
  paths.push_back(std::make_unique<vtest::TempPath>("dsv_" + name, ".store"));
  return paths.back()->str();
}

class DsvTest : public ::testing::Test {
 protected:
  void make(std::map<std::string, std::string> settings = bus_mode(), const std::string& variant = "",
            std::uint8_t node_id = 0, const std::string& store = "") {
    devices::DeviceOptions o;
    o.variant = variant;
    o.node_id = node_id;
    o.settings = std::move(settings);
    o.store_path = store;
    std::string error;
    dev = dsv::DsvDevice::create(o, error);
    ASSERT_TRUE(dev) << error;
    h = std::make_unique<vtest::CanopenHarness>(dev->node());
    h->power_on();
    boot = h->take();
  }
  void SetUp() override { make(); }

  Frames sdo(std::initializer_list<std::uint8_t> bytes) {
    std::vector<std::uint8_t> req(bytes);
    req.resize(8, 0);
    h->send(Frame(0x600u + dev->node().node_id(), req));
    return h->take();
  }
  Frame resp(std::initializer_list<std::uint8_t> bytes) { return Frame(0x580u + dev->node().node_id(), bytes); }
  std::uint32_t write(std::uint16_t index, std::uint8_t sub, std::uint32_t v, std::uint8_t size) {
    return h->write(index, sub, v, size);
  }
  std::int64_t read(std::uint16_t index, std::uint8_t sub = 0) {
    std::uint32_t abort = 0;
    auto v = h->read(index, sub, &abort);
    EXPECT_TRUE(v) << "abort " << std::hex << abort;
    if (!v) return 0;
    std::uint64_t u = 0;
    for (std::size_t i = 0; i < v->size(); ++i) u |= static_cast<std::uint64_t>((*v)[i]) << (8 * i);
    return static_cast<std::int64_t>(u);
  }
  std::uint32_t read_abort(std::uint16_t index, std::uint8_t sub = 0) {
    std::uint32_t abort = 0;
    auto v = h->read(index, sub, &abort);
    return v ? 0 : abort;
  }
  std::uint16_t status() { return static_cast<std::uint16_t>(read(0x6041)); }
  void start() {
    h->nmt(0x01, 0);
    h->take();
  }
  void power_cycle() {
    dev->power_off();
    h->run_ms(10);
    dev->power_on(h->now());
    h->run_ticks(1);
  }
  /// Imin + (Imax − Imin)·a in A for the default valve (2731 / 8192 counts, 24 V).
  static double amps(double a) { return (2731 + (8192 - 2731) * a) * 1.536 / 16384; }

  std::unique_ptr<dsv::DsvDevice> dev;
  std::unique_ptr<vtest::CanopenHarness> h;
  Frames boot;
};

}  // namespace dsvtest
