// An emulated MD2 on the frame-level test harness (node 1 unless stated), virtual time.
#pragma once

#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <string>

#include "devices/canopen/emergency.h"
#include "devices/md2/md2_device.h"
#include "tests/support/canopen_harness.h"

namespace md2test {

using vtest::Frame;
using vtest::Frames;

class Md2Test : public ::testing::Test {
 protected:
  /// Builds and powers on an MD2; the boot-up frame is taken.
  void make(std::map<std::string, std::string> settings = {}, const std::string& variant = "",
            std::uint8_t node_id = 0, const std::string& store = "") {
    devices::DeviceOptions o;
    o.variant = variant;
    o.node_id = node_id;
    o.settings = std::move(settings);
    o.store_path = store;
    std::string error;
    dev = md2::Md2Device::create(o, error);
    ASSERT_TRUE(dev) << error;
    h = std::make_unique<vtest::CanopenHarness>(dev->node());
    h->power_on();
    boot = h->take();
  }
  void SetUp() override { make(); }

  /// One SDO request (padded to 8 bytes) on 0x600+N; all frames that came back.
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
  std::uint64_t read(std::uint16_t index, std::uint8_t sub = 0) {
    std::uint32_t abort = 0;
    auto v = h->read_u(index, sub, &abort);
    EXPECT_TRUE(v) << "abort " << std::hex << abort;
    return v ? *v : 0;
  }
  std::uint32_t read_abort(std::uint16_t index, std::uint8_t sub = 0) {
    std::uint32_t abort = 0;
    auto v = h->read_u(index, sub, &abort);
    return v ? 0 : abort;
  }
  std::uint16_t status() { return static_cast<std::uint16_t>(read(0x6041)); }
  void start() {
    h->nmt(0x01, 0);
    h->take();
  }
  md2::Md2Channel& ch(int c = 1) { return dev->md2_channel(c); }

  std::unique_ptr<md2::Md2Device> dev;
  std::unique_ptr<vtest::CanopenHarness> h;
  Frames boot;
};

}  // namespace md2test
