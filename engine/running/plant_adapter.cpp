#include "engine/running/plant_adapter.h"

#include "plant/plant.h"
#include "plant/plant_yaml.h"
#include "plant/reference_plant.h"
#include "engine/loading/yaml_fields.h"

namespace scenario {

namespace {

class PhysicsPlant final : public PlantModel {
 public:
  explicit PhysicsPlant(const plant::PlantDescription& d) : plant_(d) {}
  void step(sim::Time now, sim::Duration dt) override { plant_.step(now, dt); }
  const sim::PortList& ports() const override { return plant_.ports(); }
  std::string set_parameter(std::string_view name, double value) override {
    const auto status = plant_.set_parameter(name, value);
    return status.ok() ? std::string() : status.reason();
  }
  std::optional<double> parameter(std::string_view name) const override { return plant_.parameter(name); }
  std::vector<std::string> parameter_names() const override { return plant_.parameter_names(); }

 private:
  plant::Plant plant_;
};

plant::PlantDescription reference_with_changes(const YAML::Node& section, const std::string& file) {
  MapReader r(section, file, "plant");
  if (!read_bool(r.require("reference"), file, "reference"))
    throw LoadError(r.key_mark("reference"), "reference: false is not a plant; describe the plant instead (docs/plant.md)");
  auto d = plant::reference_plant_description();
  if (auto p = r.get("parameters")) {
    MapReader pr(p, file, "plant parameters");
    for (const auto& kv : p) {
      const std::string name = kv.first.Scalar();
      pr.get(name);
      const auto dot = name.find('.');
      plant::ComponentDescription* component = nullptr;
      for (auto& c : d.components)
        if (dot != std::string::npos && c.name == name.substr(0, dot)) component = &c;
      if (!component)
        throw LoadError(mark_of(kv.first, file), "the reference plant has no component '" + name.substr(0, dot) + "'");
      plant::ParameterSetting s;
      s.name = name.substr(dot + 1);
      s.value = read_number(kv.second, file, name);
      s.name_mark = mark_of(kv.first, file);
      s.value_mark = mark_of(kv.second, file);
      std::erase_if(component->parameters, [&](const plant::ParameterSetting& o) { return o.name == s.name; });
      component->parameters.push_back(s);
    }
    pr.finish();
  }
  r.finish();
  return d;
}

}  // namespace

std::unique_ptr<PlantModel> make_physics_plant(const YAML::Node& section, const std::string& file) {
  try {
    const auto d = section.IsMap() && section["reference"] ? reference_with_changes(section, file)
                                                          : plant::parse_plant_description(section, file);
    plant::validate(d);
    return std::make_unique<PhysicsPlant>(d);
  } catch (const LoadError& e) {  // plant::DescriptionError is the same class
    if (!e.mark().file.empty()) throw;
    auto mark = e.mark();
    mark.file = file;  // a piece built in code: point at the scenario
    throw LoadError(mark, e.reason());
  }
}

}  // namespace scenario
