// A project text the placement tests share (placement_check_test.cpp, near_cut_gather_plan_test.cpp):
// a site and two materials (PlacementHead), and a 6 x 8 x 3 m room with a 4 m south window
// (PlacementOffice), to which a test adds its boxes and sensors.
#pragma once

#include <string>

namespace dayphoton::study {

inline const std::string PlacementHead = R"(site: {latitude: 37.72, longitude: -122.22, time_zone: -8}
outputs: {annual_illuminance: false, metrics: false}
materials:
  walls: {type: lambertian, reflectance: 0.5}
  glazing: {type: glass, transmittance: 0.6}
)";

inline const std::string PlacementOffice = R"(geometry:
  rooms:
    - name: office
      size: [6, 8, 3]
      materials: {floor: walls, ceiling: walls, walls: walls}
      windows:
        - {name: south, wall: south, width: 4, height: 1.5, sill: 0.9, material: glazing}
)";

}  // namespace dayphoton::study
