// Local origin: a model drawn in survey coordinates (UTM eastings of about 500 km, northings up
// to 10 000 km) is held near (0, 0, 0) for the engine, and its outputs keep the user's
// coordinates.
//
// Why: the engine stores photon positions as single-precision floats (engine/photon.h), which
// at a UTM northing of 4.2e6 m round a position by up to 0.25 m and read a room's daylight
// factor 2-3 times too high. build_scene_description therefore chooses one local origin per
// scene, in double precision, after the north rotation, and subtracts it from every position
// of the SceneDescription (surfaces, sensors, grid outlines and planes) before anything
// becomes a float; SceneDescription::world_origin_m keeps it, and every output adds it back
// (SceneDescription::world_of, world_grid). Directions (normals, the sun and sky, a BSDF's up
// vector) are unchanged by a translation, and so are the physics: the same room anywhere gives
// the same daylight, bit for bit when its translated coordinates are exact.
//
// The origin is the centre of the bounding box of the surfaces' vertices and the sensors,
// rounded to whole kilometres on each axis (LocalOriginStep_m), so it prints as a round
// number and a model drawn within 500 m of (0, 0, 0) keeps (0, 0, 0), byte for byte. What is
// left, the model's own extent, must stay within engine::PhotonCoordinateLimit_m of the
// origin: Scene::build refuses a larger model with a located error.
#pragma once

#include "dayphoton/core/scene_description.h"
#include "dayphoton/core/vec3.h"

namespace dayphoton::project {

/// The step the local origin is rounded to on each axis, metres.
inline constexpr double LocalOriginStep_m = 1000;

/// The local origin of geometry whose bounding box is [lower, upper]: its centre rounded to a
/// multiple of LocalOriginStep_m on each axis; (0, 0, 0) for an empty box (lower > upper).
Vec3 local_origin_of(const Vec3& lower_m, const Vec3& upper_m);

/// Chooses `scene`'s local origin from its surfaces' vertices and its sensors (finite ones
/// only), subtracts it from every position and records it in scene.world_origin_m (header
/// comment). Expects world_origin_m (0, 0, 0); does nothing where the origin is (0, 0, 0).
void move_to_local_origin(SceneDescription& scene);

}  // namespace dayphoton::project
