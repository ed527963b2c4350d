// The largest cosine between a fixed direction and the directions of a sky patch, in
// closed form: the exact bound that rejection emission through a port needs (port_emission.h).
//
// A patch of a Tregenza or Reinhart basis (and each cell of one, and the ground bin) is a
// rectangle in (sin altitude, azimuth): sin altitude in [z0, z1] (-1 <= z0 <= z1 <= 1) and
// azimuth in [a0, a1] (radians clockwise from north, a1 - a0 <= 2 pi), its directions
// d = (cos alt sin az, cos alt cos az, sin alt) as sky::PatchBasis::sample_direction draws
// them. For a unit vector m,
//     m . d = m_z sin(alt) + cos(alt) H cos(az - az_m),   H = |(m_x, m_y)|, az_m = atan2(m_x, m_y).
// cos(alt) >= 0, so for every altitude the largest value over the azimuths is taken at the
// same azimuth: the one of [a0, a1] nearest to az_m, where G = H cos(az - az_m) is largest.
// What remains, m_z sin(alt) + G cos(alt) = R cos(alt - alt*) with R = |(m_z, G)| and
// sin(alt*) = m_z / R, is largest at alt* if it lies in the band and at a band edge
// otherwise (Archimedes' hat-box map and the harmonic-addition identity; no sampling).
#pragma once

#include "dayphoton/core/vec3.h"

namespace dayphoton::engine {

/// max over the patch {sin altitude in [z0, z1], azimuth in [a0, a1]} of dot(m, d), for a
/// unit m. Exact up to rounding (a few ulps); see the header comment.
double max_cosine_over_patch(const Vec3& m, double z0, double z1, double a0, double a1);

}  // namespace dayphoton::engine
