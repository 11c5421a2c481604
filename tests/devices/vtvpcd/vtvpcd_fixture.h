// A VT-VPCD on a virtual bus with a scripted master, in virtual time (1 ms ticks). The card boots
// 300 ms after power-on (boot_delay_ms); the fixture takes that boot-up frame away unless asked
// to keep it.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <memory>
#include <string>

#include "devices/vtvpcd/vtvpcd_device.h"
#include "tests/support/canopen_harness.h"

namespace vtest {

class Vtvpcd {
 public:
  using Settings = std::initializer_list<std::pair<const std::string, std::string>>;
  Vtvpcd() : Vtvpcd(std::map<std::string, std::string>{}) {}
  explicit Vtvpcd(Settings settings, std::uint8_t node_id = 0, bool boot = true)
      : Vtvpcd(std::map<std::string, std::string>(settings), node_id, boot) {}
  Vtvpcd(const Vtvpcd&) = delete;
  Vtvpcd& operator=(const Vtvpcd&) = delete;
  explicit Vtvpcd(std::map<std::string, std::string> settings, std::uint8_t node_id = 0, bool boot = true) {
    devices::DeviceOptions o;
    o.node_id = node_id;
    o.settings = std::move(settings);
    std::string error;
    device = vtvpcd::VtvpcdDevice::create(o, error);
    if (!device) throw std::runtime_error(error);
    h = std::make_unique<CanopenHarness>(device->node());
    if (boot) {
      power_on();
      h->take();
    }
  }

  /// Power-on and the 300 ms boot delay: the boot-up frame (sent at power-on + 300 ms) is then
  /// waiting in take().
  void power_on() {
    device->power_on(h->now());
    h->run_ms(device->settings().boot_delay_ms + 1);
  }

  CanopenHarness& operator*() { return *h; }
  CanopenHarness* operator->() { return h.get(); }
  vtvpcd::VtvpcdDevice& dev() { return *device; }
  canopen::ObjectDictionary& od() { return device->node().od(); }
  std::uint8_t id() { return device->node().node_id(); }

  /// SDO request to this node; returns the reply's 8 data bytes (empty: no single reply).
  std::vector<std::uint8_t> sdo(std::initializer_list<std::uint8_t> req) {
    auto r = h->sdo(req);
    return r ? r->data : std::vector<std::uint8_t>{};
  }
  std::int64_t raw(std::uint16_t index) {
    const auto* e = od().entry(index, 0);
    return e->as<std::int64_t>();
  }
  /// Expedited write of a 4-byte raw value (0x23) or a 2-byte one (0x2B); 0 or the abort code.
  std::uint32_t write4(std::uint16_t index, std::int64_t raw) {
    return h->write(index, 0, static_cast<std::uint32_t>(raw), 4);
  }
  std::uint32_t write2(std::uint16_t index, std::int64_t raw) {
    return h->write(index, 0, static_cast<std::uint32_t>(raw), 2);
  }
  void set(const std::string& input, double value) {
    const auto err = device->set_input(input, value);
    if (!err.empty()) throw std::runtime_error(err);
  }
  void start() {
    h->nmt(0x01, id());
    h->run_ticks(1);
  }

  std::unique_ptr<vtvpcd::VtvpcdDevice> device;
  std::unique_ptr<CanopenHarness> h;
};

}  // namespace vtest
