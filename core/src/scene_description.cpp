#include "dayphoton/core/scene_description.h"

namespace dayphoton {

const char* material_type_name(MaterialType type) {
  switch (type) {
    case MaterialType::Lambertian: return "lambertian";
    case MaterialType::Metal: return "metal";
    case MaterialType::Mirror: return "mirror";
    case MaterialType::Glass: return "glass";
    case MaterialType::Dielectric: return "dielectric";
    case MaterialType::Translucent: return "translucent";
    case MaterialType::Opening: return "opening";
    case MaterialType::Glazing: return "glazing";
    case MaterialType::Registered: return "registered";
  }
  return "unknown";
}

std::string material_type_as_written(const MaterialSpec& material) {
  if (!material.type_as_written.empty()) return material.type_as_written;
  if (material.type == MaterialType::Registered) return material.model;
  return material_type_name(material.type);
}

const char* port_facing_name(PortFacing facing) {
  switch (facing) {
    case PortFacing::Winding: return "winding";
    case PortFacing::Auto: return "auto";
    case PortFacing::In: return "in";
    case PortFacing::Out: return "out";
  }
  return "unknown";
}

int SceneDescription::find_material(const std::string& name) const {
  for (std::size_t i = 0; i < materials.size(); ++i)
    if (materials[i].name == name) return static_cast<int>(i);
  return -1;
}

SensorGrid SceneDescription::world_grid(const SensorGrid& grid) const {
  SensorGrid world = grid;
  if (world_origin_m == Vec3{0, 0, 0}) return world;
  for (SensorPoint& p : world.points) p.position = world_of(p.position);
  for (Vec3& v : world.outline) v = world_of(v);
  world.plane_height_m = grid.plane_height_m + dot(grid.plane_normal, world_origin_m);
  return world;
}

std::vector<SensorPoint> SceneDescription::world_points(const std::vector<SensorPoint>& points) const {
  std::vector<SensorPoint> world = points;
  if (world_origin_m == Vec3{0, 0, 0}) return world;
  for (SensorPoint& p : world) p.position = world_of(p.position);
  return world;
}

}  // namespace dayphoton
