// TensorTreeBsdfData: see tensor_tree_bsdf_data.h.
#include "dayphoton/core/tensor_tree_bsdf_data.h"

#include <algorithm>
#include <cmath>

#include "dayphoton/core/shirley_chiu.h"

namespace dayphoton {
namespace {
constexpr double Pi = 3.14159265358979323846;
}

std::size_t TensorTreeBsdfData::slice_cell_count() const {
  std::size_t total = 0;
  for (int side = 0; side < 2; ++side) {
    const int l = std::max({1, trees[side].max_log2, trees[2 + side].max_log2});
    const int n = 1 << (l - 1);
    for (int k = 0; k < n; ++k) {
      const double u0 = (k + 0.5) / static_cast<double>(1 << l);
      total += trees[side].slice_cell_count(&u0) + trees[2 + side].slice_cell_count(&u0);
    }
  }
  return total;
}

void TensorTreeBsdfData::build_slices() {
  for (int side = 0; side < 2; ++side) {
    const int l = std::max({1, trees[side].max_log2, trees[2 + side].max_log2});
    incident_log2[side] = l;
    const int n = 1 << (l - 1);
    slices[side].assign(static_cast<std::size_t>(n), Slice{});
    for (int k = 0; k < n; ++k) {
      Slice& s = slices[side][static_cast<std::size_t>(k)];
      const double u0 = slice_coordinate(side, k);
      double sum = 0;
      auto add = [&](double u, double v, double size, float value) {
        s.cells.push_back({static_cast<float>(u), static_cast<float>(v), static_cast<float>(size), value});
        sum += static_cast<double>(value) * Pi * size * size;
        s.cumulative.push_back(sum);
      };
      trees[side].for_each_slice_cell(&u0, add);
      s.transmitted = s.cells.size();
      s.transmittance = sum;
      trees[2 + side].for_each_slice_cell(&u0, add);
      s.albedo = sum;
    }
  }
}

int TensorTreeBsdfData::slice_of(int side, const Vec3& d) const {
  const double r = std::min(1.0, std::sqrt(d.x * d.x + d.y * d.y));
  const int l = incident_log2[side];
  const int k = static_cast<int>(std::floor((0.5 - 0.5 * r) * static_cast<double>(1 << l)));
  return std::clamp(k, 0, (1 << (l - 1)) - 1);
}

double TensorTreeBsdfData::slice_coordinate(int side, int k) const {
  return (k + 0.5) / static_cast<double>(1 << incident_log2[side]);
}

void TensorTreeBsdfData::outgoing_square(const Vec3& d, const Vec3& o, double& u, double& v) {
  const double phi = std::atan2(d.y, d.x), c = std::cos(phi), s = std::sin(phi);
  shirley_chiu_disc_to_square(o.x * c + o.y * s, -o.x * s + o.y * c, u, v);
  u = std::clamp(u, 0.0, std::nextafter(1.0, 0.0));
  v = std::clamp(v, 0.0, std::nextafter(1.0, 0.0));
}

Vec3 TensorTreeBsdfData::outgoing_direction(const Vec3& d, double u, double v, double z_sign) {
  double x = 0, y = 0;
  shirley_chiu_square_to_disc(u, v, x, y);
  const double phi = std::atan2(d.y, d.x), c = std::cos(phi), s = std::sin(phi);
  const double z = std::sqrt(std::max(0.0, 1.0 - x * x - y * y));
  return {x * c - y * s, x * s + y * c, z_sign * z};
}

double TensorTreeBsdfData::value(const Vec3& d, const Vec3& o) const {
  const int side = side_of(d);
  if (side < 0 || o.z == 0) return 0.0;
  const bool transmitted = (o.z > 0) == (d.z > 0);
  double pos[3];
  pos[0] = slice_coordinate(side, slice_of(side, d));
  outgoing_square(d, o, pos[1], pos[2]);
  return trees[transmitted ? side : 2 + side].lookup(pos);
}

}  // namespace dayphoton
