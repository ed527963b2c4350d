// The measured-BSDF material (type `bsdf`, docs/materials.md "Measured BSDF (Klems)"): its
// parameters, for importers that read the BSDF file themselves (the RADIANCE `BSDF`
// modifier) and for the scene's checks. The model is engine/src/bsdf_material.cpp.
#pragma once

#include <memory>
#include <string>

#include "dayphoton/core/klems_bsdf_data.h"
#include "dayphoton/core/scene_description.h"
#include "dayphoton/core/vec3.h"

namespace dayphoton::engine {

/// The registry's type name of the model.
constexpr const char* BsdfMaterialType = "bsdf";

struct BsdfMaterialParameters : MaterialParameters {
  std::shared_ptr<const KlemsBsdfData> data;
  /// The BSDF's up vector, world coordinates (not unit, not perpendicular to the surfaces
  /// needed; it must not be parallel to a surface's normal: Scene::build checks).
  Vec3 up{0, 0, 1};
};

/// A `bsdf` material named `name` with these parameters (location left empty).
MaterialSpec bsdf_material_spec(const std::string& name, std::shared_ptr<const KlemsBsdfData> data, const Vec3& up);

/// The parameters of a `bsdf` material, or nullptr for any other material.
const BsdfMaterialParameters* bsdf_parameters(const MaterialSpec& spec);

}  // namespace dayphoton::engine
