// North rotation: how model coordinates become world coordinates (+X east, +Y true north,
// +Z up, the RADIANCE axes).
//
// Convention (DESIGN.md section 4, Site::north_deg in project.h): the site's angle
// `rotation_to_true_north_deg` is measured clockwise, seen from above, from the model's +Y
// axis to true north. With 90 degrees, true north lies along model +X, so model +X must
// become world +Y: the model is rotated COUNTER-clockwise about +Z by the same angle,
//
//   x_world = x cos(a) - y sin(a),   y_world = x sin(a) + y cos(a),   z_world = z,
//
// with a = rotation_to_true_north_deg in radians. Positions and directions (normals)
// rotate alike (rotation about the world origin); z is unchanged.
#pragma once

#include "dayphoton/core/vec3.h"

namespace dayphoton::project {

/// A model-space point or direction in world coordinates (see the convention above).
Vec3 model_to_world(const Vec3& v, double rotation_to_true_north_deg);

/// Inverse of model_to_world.
Vec3 world_to_model(const Vec3& v, double rotation_to_true_north_deg);

}  // namespace dayphoton::project
