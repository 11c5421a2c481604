#include "tests/engine/test_world.h"

#include <cmath>

#include "devices/canopen/emergency.h"
#include "devices/canopen/standard_objects.h"
#include "engine/loading/yaml_fields.h"

namespace vtest {

namespace {

using canopen::Access;
using canopen::DataType;

/// A position sensor and velocity actuator on one node.
class AxisDevice final : public devices::Device, public canopen::Application {
 public:
  explicit AxisDevice(std::uint8_t node_id) {
    canopen::ObjectDictionary od;
    canopen::CommunicationProfile p;
    p.device_type = 0x00000194;
    p.vendor_id = 0x00ABCDEF;
    p.product_code = 7;
    p.device_name = "vplant test axis";
    p.error_behaviour = true;
    canopen::add_communication_objects(od, p);
    od.add_var(0x2000, "U8 rw", DataType::Unsigned8, Access::ReadWrite, 7);
    auto& limited = od.add_var(0x2001, "I16 limited", DataType::Integer16, Access::ReadWrite, 0);
    limited.low_limit = canopen::ObjectDictionary::encode(DataType::Integer16, -100);
    limited.high_limit = canopen::ObjectDictionary::encode(DataType::Integer16, 100);
    od.add_var(0x2002, "Text", DataType::VisibleString, Access::ReadWrite,
               canopen::ObjectDictionary::encode(DataType::VisibleString, "hello segmented world"));
    od.add_var(0x6000, "Position", DataType::Integer32, Access::ReadOnly, 0, true).persistent = false;
    od.add_var(0x6001, "Velocity command", DataType::Integer32, Access::ReadWrite, 0, true).persistent = false;
    canopen::add_tpdo(od, 1, {.cob_base = 0x180, .transmission_type = 1, .mapping = {0x60000020}});
    canopen::add_rpdo(od, 1, {.cob_base = 0x200, .transmission_type = 255, .mapping = {0x60010020}});
    node_ = std::make_unique<canopen::Node>("axis", std::move(od), canopen::NodePolicy{}, node_id);
    node_->set_application(this);
  }

  canopen::Node& node() override { return *node_; }
  sim::PortList ports() override {
    return {{"velocity", sim::PortDirection::Output, "m/s", &velocity_, "velocity command to the axis"},
            {"position", sim::PortDirection::Input, "m", &position_, "measured position"}};
  }
  std::vector<devices::FaultInfo> faults() const override { return {{"sensor_lost", "EMCY 0x7300, position frozen"}}; }
  std::string inject_fault(std::string_view name, bool active) override {
    if (name != "sensor_lost") return Device::inject_fault(name, active);
    sensor_lost_ = active;
    if (active) node_->emergency().raise(0x7300, 0x81);
    else node_->emergency().clear(0x7300);
    return {};
  }

  void before_tpdo(int) override {
    if (!sensor_lost_) node_->od().set<std::int32_t>(0x6000, 0, static_cast<std::int32_t>(std::lround(position_ * 1e6)));
  }
  void process(sim::Time, sim::Duration) override {
    velocity_ = node_->nmt_state() == canopen::NmtState::Operational ? node_->od().get<std::int32_t>(0x6001) * 1e-6 : 0.0;
  }
  void on_reset_application() override { velocity_ = 0; }

 private:
  std::unique_ptr<canopen::Node> node_;
  double velocity_ = 0, position_ = 0;
  bool sensor_lost_ = false;
};

/// position' = gain · velocity_command + drift
class AxisPlant final : public scenario::PlantModel {
 public:
  AxisPlant(double gain, double drift) : gain_(gain), drift_(drift) {
    ports_ = {{"axis.velocity_command", sim::PortDirection::Input, "m/s", &command_, ""},
              {"axis.position", sim::PortDirection::Output, "m", &position_, ""},
              {"axis.velocity", sim::PortDirection::Output, "m/s", &velocity_, ""}};
  }
  void step(sim::Time, sim::Duration dt) override {
    velocity_ = gain_ * command_ + drift_;
    position_ += velocity_ * sim::seconds(dt);
  }
  const sim::PortList& ports() const override { return ports_; }
  std::string set_parameter(std::string_view name, double value) override {
    if (name == "axis.gain") {
      if (value < 0 || value > 10) return "axis.gain out of range [0, 10]";
      gain_ = value;
    } else if (name == "axis.drift") {
      drift_ = value;
    } else {
      return "no parameter '" + std::string(name) + "'";
    }
    return {};
  }
  std::optional<double> parameter(std::string_view name) const override {
    if (name == "axis.gain") return gain_;
    if (name == "axis.drift") return drift_;
    return std::nullopt;
  }

 private:
  double gain_, drift_;
  double command_ = 0, position_ = 0, velocity_ = 0;
  sim::PortList ports_;
};

}  // namespace

scenario::Environment test_environment() {
  static const devices::Product kAxis{
      "axis", "test axis", {}, [](const devices::DeviceOptions& o, std::string& error) -> std::unique_ptr<devices::Device> {
        if (!o.settings.empty()) {
          error = "unknown setting '" + o.settings.begin()->first + "'";
          return nullptr;
        }
        return std::make_unique<AxisDevice>(o.node_id ? o.node_id : 5);
      },
      nullptr};
  scenario::Environment env;
  env.find_product = [](const std::string& name) -> const devices::Product* {
    return name == "axis" ? &kAxis : devices::find_product(name);
  };
  env.product_names = [] { return std::vector<std::string>{"axis"}; };
  env.make_plant = [](const YAML::Node& section, const std::string& file) -> std::unique_ptr<scenario::PlantModel> {
    // The reference plant (and its parameter overrides) through the real adapter, as `vplant run`
    // builds it: its errors are plant/'s own checks, not this test plant's.
    if (section.IsMap() && section["reference"]) {
      static const auto physics = scenario::default_environment().make_plant;
      if (physics) return physics(section, file);
    }
    scenario::MapReader r(section, file, "plant");
    scenario::MapReader a(r.require("axis"), file, "plant component 'axis'");
    double gain = 1, drift = 0;
    if (auto g = a.get("gain")) gain = scenario::read_number(g, file, "gain", 0, 10);
    if (auto d = a.get("drift")) drift = scenario::read_number(d, file, "drift");
    a.finish();
    r.finish();
    return std::make_unique<AxisPlant>(gain, drift);
  };
  return env;
}

}  // namespace vtest
