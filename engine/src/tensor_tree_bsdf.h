// TensorTreeBsdf: scattering by a tensor-tree BSDF (TensorTree3 or 4; core/tensor_tree_bsdf_data.h;
// docs/materials.md "Tensor-tree BSDF"), with KlemsBsdf's interface and frame (klems_bsdf.h,
// bsdf_frame.h UpFrame), so the `bsdf` material uses either.
//
// Light arriving along d on a side is given the slice of its incident cell: leaf cells c of
// the outgoing square, each of projected solid angle pi s_c^2 and BSDF f_c. sample() picks a
// cell with probability f_c pi s_c^2 / A, A = sum_c f_c pi s_c^2 (the directional albedo,
// transmitted and reflected cells together), then a point uniform in the cell's square,
// mapped to the disc by Shirley-Chiu (area preserving, so uniform in projected solid angle
// over the cell's pre-image) and (TensorTree3) turned back by the incident azimuth. Its density per
// steradian is therefore p(o) = f(d, o) |cos o| / A and every sample weighs A, exactly as for
// a Klems matrix; eval() is the tree's f at the slice, pdf() = eval |cos| / A.
#pragma once

#include <memory>
#include <optional>

#include "dayphoton/core/klems_bsdf_data.h"
#include "dayphoton/core/vec3.h"
#include "klems_bsdf.h"

namespace dayphoton::engine {

class TensorTreeBsdf {
 public:
  /// `data->tensor_tree` must be set.
  TensorTreeBsdf(std::shared_ptr<const KlemsBsdfData> data, const Vec3& up);

  std::optional<KlemsBsdf::Sample> sample(const Vec3& incoming, const Vec3& normal, double u_cell, double u1,
                                          double u2) const;
  double eval(const Vec3& incoming, const Vec3& outgoing, const Vec3& normal) const;
  double pdf(const Vec3& incoming, const Vec3& outgoing, const Vec3& normal) const;
  double albedo(const Vec3& incoming, const Vec3& normal) const;
  double transmittance(const Vec3& incoming, const Vec3& normal) const;

 private:
  const TensorTreeBsdfData::Slice* slice(const Vec3& local_incoming) const;

  std::shared_ptr<const KlemsBsdfData> m_data;
  const TensorTreeBsdfData* m_tree = nullptr;
  Vec3 m_up;
};

}  // namespace dayphoton::engine
