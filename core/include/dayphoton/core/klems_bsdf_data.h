// KlemsBsdfData: a measured or computed BSDF on a Klems basis, as an LBNL WINDOW / IGSDB BSDF
// XML file gives it (read by project/bsdf_xml.h, used by the engine's `bsdf` material,
// docs/materials.md "Measured BSDF (Klems)"). Visible (photopic) values only: the engine
// applies them to all three RGB channels.
//
// Orientation (the one RADIANCE's BSDF primitive uses, and LBNL WINDOW's): the local frame
// has z along the surface's normal, y along the "up" vector projected onto the surface and
// x = y x z. WINDOW's FRONT side (the exterior of a window) is the side the normal points
// AWAY from (local -z), its BACK side (the room) the side the normal points to; so
// "Transmission Front" is light that arrives from -z and leaves into +z. (RADIANCE's bsdf_m.c
// reads the XML's "Front" blocks as its back-side data for this reason.)
//
// Patch of a direction: for incoming and outgoing light alike, the Klems patch of the
// PROPAGATION direction v in the local frame, theta = acos |v.z|, azimuth atan2(v.y, v.x)
// (KlemsBasis::patch). Under this rule the straight-through direction and the mirror
// direction of incoming patch i are both in outgoing patch i, so a clear pane's matrices are
// diagonal (WINDOW's convention; G. Ward, "Radiance BSDF support", bsdf_m.c: incoming
// vectors are the outgoing basis' vectors with x and y negated and pointing at the source).
//
// Values: f(i, j), 1/sr, stored [incoming * size + outgoing]. The reader has checked every
// value finite and >= 0, and sum_j (T + R)(i, j) Lambda_j <= 1 + BsdfAlbedoTolerance per
// incoming patch and side.
//
// Tensor trees: a TensorTree3/4 file (core/tensor_tree_bsdf_data.h) is read into this same
// struct with `tensor_tree` set. The BSDF is then the tree (the engine evaluates and samples
// it); the matrices hold its projection onto the LBNL/Klems Full basis for the summaries that
// read matrices (core/bsdf_xml.cpp project_on_klems): each incoming patch at its centre
// direction, its hemispherical T and R exact, their split over outgoing patches by 1/64
// sub-squares of the tree's square (a single patch's value within about 26 %).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "dayphoton/core/klems_basis.h"
#include "dayphoton/core/tensor_tree_bsdf_data.h"

namespace dayphoton {

/// How far above 1 the hemispherical T + R of an incoming patch may be (measurement and
/// rounding noise of real files); RADIANCE's bsdf_m.c accepts up to 1.01 too.
constexpr double BsdfAlbedoTolerance = 0.01;

struct KlemsBsdfData {
  std::string file;  ///< the file as written in the project (for messages)
  std::string content_sha256;  ///< of the file's bytes (for cache keys)
  /// The layer's <Material><DeviceType> as the file writes it, trimmed ("Venetian blind",
  /// "Integral" ...); empty when the file has none. It names what the matrix stands for: a
  /// glazing or a shading device (study/shading_materials.h reads it for LM-83's verdicts).
  std::string device_type;
  KlemsBasis basis;
  std::vector<double> transmission_front, transmission_back, reflection_front, reflection_back;
  /// Set for a tensor-tree file: the BSDF itself (the matrices are its Klems projection).
  std::shared_ptr<const TensorTreeBsdfData> tensor_tree;

  double value(const std::vector<double>& matrix, int incoming, int outgoing) const {
    return matrix[static_cast<std::size_t>(incoming) * static_cast<std::size_t>(basis.size()) +
                  static_cast<std::size_t>(outgoing)];
  }
  /// Hemispherical transmittance and reflectance of incoming patch i, front or back.
  double hemispherical(const std::vector<double>& matrix, int incoming) const;
};

}  // namespace dayphoton
