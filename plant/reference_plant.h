// The reference machine (docs/plant.md, "The reference plant"): an electric motor at constant speed
// drives an A4VSO-class pump; its pressure line, protected by a relief valve, feeds two NG6 4/3
// proportional valves - valve_cyl drives the 63/36x500 differential cylinder cyl, valve_motor
// drives the hydraulic motor motor turning the flywheel shaft shaft. Tank at 0 bar gauge.
// scenarios/plant/reference-plant.plant.yaml is the same description as YAML.
#pragma once

#include "plant/plant_description.h"

namespace plant {

PlantDescription reference_plant_description();

}  // namespace plant
