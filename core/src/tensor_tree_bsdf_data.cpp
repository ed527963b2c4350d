// TensorTreeBsdfData: see tensor_tree_bsdf_data.h.
#include "dayphoton/core/tensor_tree_bsdf_data.h"

#include <algorithm>
#include <cmath>

#include "dayphoton/core/shirley_chiu.h"

namespace dayphoton {
namespace {
constexpr double Pi = 3.14159265358979323846;
}

int TensorTreeBsdfData::side_log2(int side) const {
  return std::max({1, trees[side].max_log2, trees[2 + side].max_log2});
}

int TensorTreeBsdfData::slice_count_of(int l) const { return ndim == 3 ? 1 << (l - 1) : 1 << (2 * l); }

void TensorTreeBsdfData::incident_of(int l, int k, double* incident) const {
  const double n = static_cast<double>(1 << l);
  if (ndim == 3) {
    incident[0] = (k + 0.5) / n;
  } else {
    incident[0] = ((k >> l) + 0.5) / n;
    incident[1] = ((k & ((1 << l) - 1)) + 0.5) / n;
  }
}

std::size_t TensorTreeBsdfData::slice_cell_count() const {
  std::size_t total = 0;
  for (int side = 0; side < 2; ++side) {
    const int l = side_log2(side);
    const int n = slice_count_of(l);
    for (int k = 0; k < n; ++k) {
      double incident[2] = {0, 0};
      incident_of(l, k, incident);
      total += trees[side].slice_cell_count(incident) + trees[2 + side].slice_cell_count(incident);
    }
  }
  return total;
}

void TensorTreeBsdfData::build_slices() {
  for (int side = 0; side < 2; ++side) {
    const int l = side_log2(side);
    incident_log2[side] = l;
    const int n = slice_count_of(l);
    slices[side].assign(static_cast<std::size_t>(n), Slice{});
    for (int k = 0; k < n; ++k) {
      Slice& s = slices[side][static_cast<std::size_t>(k)];
      double incident[2] = {0, 0};
      slice_incident(side, k, incident);
      double sum = 0;
      auto add = [&](double u, double v, double size, float value) {
        s.cells.push_back({static_cast<float>(u), static_cast<float>(v), static_cast<float>(size), value});
        sum += static_cast<double>(value) * Pi * size * size;
        s.cumulative.push_back(sum);
      };
      trees[side].for_each_slice_cell(incident, add);
      s.transmitted = s.cells.size();
      s.transmittance = sum;
      trees[2 + side].for_each_slice_cell(incident, add);
      s.albedo = sum;
    }
  }
}

int TensorTreeBsdfData::slice_of(int side, const Vec3& d) const {
  const int l = incident_log2[side], n = 1 << l;
  if (ndim == 3) {
    const double r = std::min(1.0, std::sqrt(d.x * d.x + d.y * d.y));
    const int k = static_cast<int>(std::floor((0.5 - 0.5 * r) * static_cast<double>(n)));
    return std::clamp(k, 0, (n >> 1) - 1);
  }
  double a = 0, b = 0;
  shirley_chiu_disc_to_square(d.x, d.y, a, b);
  const int ia = std::clamp(static_cast<int>(std::floor(a * n)), 0, n - 1);
  const int ib = std::clamp(static_cast<int>(std::floor(b * n)), 0, n - 1);
  return ia * n + ib;
}

void TensorTreeBsdfData::slice_incident(int side, int k, double* incident) const {
  incident_of(incident_log2[side], k, incident);
}

void TensorTreeBsdfData::outgoing_square(const Vec3& d, const Vec3& o, double& u, double& v) const {
  if (ndim == 3) {
    const double phi = std::atan2(d.y, d.x), c = std::cos(phi), s = std::sin(phi);
    shirley_chiu_disc_to_square(o.x * c + o.y * s, -o.x * s + o.y * c, u, v);
  } else {
    shirley_chiu_disc_to_square(o.x, o.y, u, v);
  }
  u = std::clamp(u, 0.0, std::nextafter(1.0, 0.0));
  v = std::clamp(v, 0.0, std::nextafter(1.0, 0.0));
}

Vec3 TensorTreeBsdfData::outgoing_direction(const Vec3& d, double u, double v, double z_sign) const {
  double x = 0, y = 0;
  shirley_chiu_square_to_disc(u, v, x, y);
  const double z = std::sqrt(std::max(0.0, 1.0 - x * x - y * y));
  if (ndim != 3) return {x, y, z_sign * z};
  const double phi = std::atan2(d.y, d.x), c = std::cos(phi), s = std::sin(phi);
  return {x * c - y * s, x * s + y * c, z_sign * z};
}

double TensorTreeBsdfData::value(const Vec3& d, const Vec3& o) const {
  const int side = side_of(d);
  if (side < 0 || o.z == 0) return 0.0;
  const bool transmitted = (o.z > 0) == (d.z > 0);
  double pos[4] = {0, 0, 0, 0};
  slice_incident(side, slice_of(side, d), pos);
  outgoing_square(d, o, pos[ndim - 2], pos[ndim - 1]);
  return trees[transmitted ? side : 2 + side].lookup(pos);
}

}  // namespace dayphoton
