#include "dayphoton/study/shading_materials.h"

#include <algorithm>
#include <cctype>

#include "dayphoton/engine/bsdf_material.h"

namespace dayphoton::study {

bool names_shading_device(std::string_view device_type) {
  std::string lower(device_type);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (const char* word : {"blind", "shade", "screen", "shutter", "louver", "louvre", "drape", "curtain", "awning"})
    if (lower.find(word) != std::string::npos) return true;
  return false;
}

std::optional<std::string> operable_shading_reason(const MaterialSpec& material) {
  if (material.shading == ShadingRole::Operable) return std::string("`shading: operable`");
  if (material.shading == ShadingRole::Fixed) return std::nullopt;
  if (const engine::BsdfMaterialParameters* p = engine::bsdf_parameters(material); p && p->data)
    if (names_shading_device(p->data->device_type))
      return "its BSDF file's DeviceType is '" + p->data->device_type +
             "'; say `shading: fixed` on the material if it does not move";
  return std::nullopt;
}

}  // namespace dayphoton::study
