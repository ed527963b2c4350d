// PortSet: the photon ports of a scene, kept apart for emission (DESIGN.md section 5).
//
// A port is a planar polygon (a surface with port = true, usually glazing) through which
// photons from distant sources (sky patches, sun bins) enter the room. Photon emission
// needs a uniform point on the port: Schregle's thesis (seeds/000, section 4.1.3) emits
// from port positions distributed uniformly by area, with the flux scaled by the port area,
// i.e. the position pdf is 1 / area (per m^2).
//
// Sampling: the port is triangulated; a triangle is chosen with probability proportional to
// its area (the first uniform number, then rescaled and reused), and a point is placed
// uniformly in it with the square-root warp (Shirley & Chiu; Pharr, Jakob & Humphreys,
// "Physically Based Rendering", 4th ed., section A.5.5):
//   b0 = 1 - sqrt(u1), b1 = u2 * sqrt(u1), p = b0 * a + b1 * b + (1 - b0 - b1) * c.
//
// Ports are ALSO real geometry in the Embree scene (the glazing can be hit from inside);
// Hit::port names the port a hit lies on.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "dayphoton/core/scene_description.h"
#include "dayphoton/core/source_location.h"
#include "dayphoton/core/vec3.h"

namespace dayphoton::engine {

/// How a port's inward side was decided (engine/port_facing.h).
enum class PortSideReason {
  Generated,     ///< PortFacing::Winding: the generator winds it into the room; not tested
  Sky,           ///< PortFacing::Auto: the side whose test rays escape to the sky is outside
  Declared,      ///< PortFacing::In/Out, and the test rays agree or cannot tell
  Ambiguous,     ///< PortFacing::Auto, and the rays cannot tell (both sides see the sky, or
                 ///< neither): the winding is kept; a project must declare the facing
  Contradicted,  ///< PortFacing::In/Out, but the rays say the declared room side sees the sky
};

struct Port {
  int surface = -1;    ///< index into SceneDescription::surfaces
  std::string name;    ///< the surface's name
  double area_m2 = 0;  ///< sum of the triangle areas
  /// Unit normal pointing INTO the room: the polygon's winding normal, or its opposite when
  /// against_winding (ports face either way; Scene::build decides, engine/port_facing.h).
  /// Port emission and the port's own scattering rely on this side.
  Vec3 normal;
  bool against_winding = false;  ///< normal = -(winding normal)
  PortSideReason side_reason = PortSideReason::Generated;
  /// Share of the facing test's rays that escape to the sky from the side the winding normal
  /// points to, and from the other side (both 0 when not tested: Generated).
  double sky_fraction_winding = 0, sky_fraction_opposite = 0;
  Vec3 centroid;       ///< area-weighted centroid, metres
  std::vector<std::array<Vec3, 3>> triangles;
  std::vector<double> cumulative_area_m2;  ///< running sum of triangle areas
  /// For a port that is a parallelogram (most windows): corner and the two edge vectors, for
  /// samplers that want strata aligned with its edges (the direct component's port pieces).
  std::optional<std::array<Vec3, 3>> parallelogram;
  SourceLocation location;
};

/// A uniform point on a port.
struct PortSample {
  Vec3 position;          ///< metres, on the port polygon
  Vec3 normal;            ///< the port's unit normal
  double pdf_per_m2 = 0;  ///< 1 / area of the port
};

class PortSet {
 public:
  /// Add the port made of surface `surface_index` (`surface`) cut into `triangles`
  /// (indices into surface.vertices, e.g. from triangulate_polygon). Zero-area triangles
  /// are dropped. Returns the new port's index. Throws std::invalid_argument if the total
  /// area is zero.
  int add(int surface_index, const Surface& surface,
          const std::vector<std::array<std::uint32_t, 3>>& triangles);

  std::size_t size() const { return m_ports.size(); }
  bool empty() const { return m_ports.empty(); }
  const Port& operator[](std::size_t i) const { return m_ports[i]; }
  const std::vector<Port>& ports() const { return m_ports; }

  /// Sum of all port areas, m^2.
  double total_area_m2() const;

  /// Port index of a surface, or -1 if that surface is not a port.
  int port_of_surface(int surface_index) const;

  /// Make `normal` of port `port` point along (against_winding = false) or against its
  /// polygon's winding normal, and record why. Throws std::out_of_range for a bad index.
  void orient(std::size_t port, bool against_winding, PortSideReason reason, double sky_fraction_winding,
              double sky_fraction_opposite);

  /// A point uniformly distributed by area on port `port`, from two independent uniform
  /// numbers in [0, 1); pdf = 1 / area. Throws std::out_of_range for a bad port index.
  PortSample sample(std::size_t port, double u1, double u2) const;

 private:
  std::vector<Port> m_ports;
};

}  // namespace dayphoton::engine
