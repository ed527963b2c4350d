// Dielectric panels in front of a window (docs/daylight-systems.md): prismatic panels and
// lamella panels (Y-glass). Both are closed solids of a dielectric material (the
// dielectric's front side is the outside, so every face points out of its solid) extruded
// across the window's width (u from 0 to the width; the end caps are solid faces too).
//
// Depth t is measured from the panel's face nearest the wall plane, away from it; the
// panel is `offset` from the wall plane on the system's side: w = s (offset + t), with s =
// -1 inside the room and +1 outside.
//
// Prismatic panel: n = floor(H / pitch) isosceles prisms of base `pitch` (vertical, in the
// panel plane) and apex angle alpha, height h = (pitch / 2) / tan(alpha / 2), centred on
// the covered heights H. Apexes point into the room (`apex: inward`) or outside. With a
// backing plate of thickness b the whole panel is one solid (a saw-tooth polygon closed by
// the plate's flat face); without, every prism is its own triangular solid, neighbours
// touching along a base edge.
//
// Lamella panel (seeds/000 section 4.2.1: INGLAS Y-glass, a plexiglass panel cut by air
// lamellae inclined 7 degrees toward the interior that redirect light by total internal
// reflection): a panel of thickness T whose lamellae are planes across the panel inclined
// by beta, the room-side edge lower for beta > 0, spaced `spacing` apart vertically
// (measured at mid-depth) and centred on the covered heights; the panel's top and bottom
// edges are horizontal. Each lamella is an air gap of width `gap` perpendicular to it
// (gap / cos beta vertically), so the panel is a stack of dielectric strips, each a
// quadrilateral solid between two lamellae (or a lamella and the panel's edge). Light
// inside a strip meets a lamella as a dielectric-to-air interface: beyond the critical
// angle it is totally reflected (the "Y" path), otherwise it crosses the gap and the next
// strip's parallel face, continuing in its original direction.
#include <cmath>

#include "dayphoton/core/units.h"
#include "system_generators.h"

namespace dayphoton::project::detail {

namespace {

/// (t, v) of the panel -> (w, v) of the window frame.
std::vector<P2> to_wv(const MountedBuild& b, double offset_m, const std::vector<P2>& tv) {
  std::vector<P2> wv;
  for (const P2& p : tv) wv.push_back({b.side_sign() * (offset_m + p.x), p.y});
  return wv;
}

}  // namespace

bool generate_prismatic_panel(const MountedBuild& b, const PrismaticPanelSpec& p) {
  const int mat = b.material("material", p.material);
  if (!b.check_dielectric("material", mat)) return false;
  double v0 = 0, v1 = 0;
  if (!b.covered_heights(p.bottom_m, p.top_m, v0, v1)) return false;
  const int n = static_cast<int>(std::floor((v1 - v0) / p.pitch_m + 1e-9));
  if (n < 1) {
    b.error("pitch", "has a pitch of " + format_number(p.pitch_m) + " m, more than the covered height (" +
                         format_number(v1 - v0) + " m)");
    return false;
  }
  const double height = 0.5 * p.pitch_m / std::tan(0.5 * deg_to_rad(p.apex_angle_deg));
  const double vb = 0.5 * (v0 + v1) - 0.5 * n * p.pitch_m;
  // Which way the apexes point along t (t grows away from the wall plane).
  const bool apex_toward_wall = (b.spec.mount.side == MountSide::Interior) == p.apex_outward;
  const double thickness = p.backing_m + height;
  const double t_base = apex_toward_wall ? height : p.backing_m;
  const double t_apex = apex_toward_wall ? 0.0 : thickness;
  const double u1 = b.frame.width_m;
  if (p.backing_m == 0) {
    for (int k = 0; k < n; ++k) {
      const double v = vb + k * p.pitch_m;
      const std::vector<P2> tri{{t_base, v}, {t_base, v + p.pitch_m}, {t_apex, v + 0.5 * p.pitch_m}};
      add_prism(b.wv_plane(), to_wv(b, p.offset_m, tri), 0, u1, {mat, mat, mat}, mat,
                b.spec.name + ".prism" + std::to_string(k + 1), b.spec.location, b.out);
    }
    return true;
  }
  const double t_back = apex_toward_wall ? thickness : 0.0;
  std::vector<P2> saw{{t_back, vb}, {t_base, vb}};
  for (int k = 0; k < n; ++k) {
    saw.push_back({t_apex, vb + (k + 0.5) * p.pitch_m});
    saw.push_back({t_base, vb + (k + 1) * p.pitch_m});
  }
  saw.push_back({t_back, vb + n * p.pitch_m});
  add_prism(b.wv_plane(), to_wv(b, p.offset_m, saw), 0, u1, std::vector<int>(saw.size(), mat), mat,
            b.spec.name + ".panel", b.spec.location, b.out);
  return true;
}

bool generate_lamella_panel(const MountedBuild& b, const LamellaPanelSpec& p) {
  const int mat = b.material("material", p.material);
  if (!b.check_dielectric("material", mat)) return false;
  double v0 = 0, v1 = 0;
  if (!b.covered_heights(p.bottom_m, p.top_m, v0, v1)) return false;
  const double beta = deg_to_rad(p.lamella_angle_deg);
  const double slope = std::tan(beta), gap_v = p.gap_m / std::cos(beta), thick = p.thickness_m;
  const int strips = static_cast<int>(std::floor((v1 - v0) / p.spacing_m + 1e-9));
  if (strips < 1) {
    b.error("spacing", "has a lamella spacing of " + format_number(p.spacing_m) +
                           " m, more than the covered height (" + format_number(v1 - v0) + " m)");
    return false;
  }
  // A strip must stay open at both faces: the lamella drops thick * |tan beta| across the
  // panel, plus the gap.
  if (p.spacing_m <= thick * std::fabs(slope) + gap_v) {
    b.error("spacing", "has lamellae " + format_number(p.spacing_m) + " m apart, not more than the " +
                           format_number(thick * std::fabs(slope) + gap_v) +
                           " m a lamella drops across the panel plus its gap: the strips would close");
    return false;
  }
  const int lamellae = strips - 1;
  const double mid = 0.5 * (v0 + v1);
  // Height of lamella j (1..lamellae) at depth d from the outside face.
  auto lamella = [&](int j, double d) {
    return mid + (j - 0.5 * (lamellae + 1)) * p.spacing_m - (d - 0.5 * thick) * slope;
  };
  auto lower = [&](int k, double d) { return k == 0 ? v0 : lamella(k, d) + 0.5 * gap_v; };
  auto upper = [&](int k, double d) { return k == lamellae ? v1 : lamella(k + 1, d) - 0.5 * gap_v; };
  // d (from the outside-facing face) -> t (from the wall-side face).
  const bool interior = b.spec.mount.side == MountSide::Interior;
  auto t_of = [&](double d) { return interior ? d : thick - d; };
  for (int k = 0; k <= lamellae; ++k) {
    if (!(upper(k, 0) > lower(k, 0) && upper(k, thick) > lower(k, thick))) {
      b.error("spacing", "leaves no room for strip " + std::to_string(k + 1) +
                             " at the panel's edge: increase the covered height or the spacing");
      return false;
    }
    const std::vector<P2> strip{{t_of(0), lower(k, 0)}, {t_of(thick), lower(k, thick)},
                                {t_of(thick), upper(k, thick)}, {t_of(0), upper(k, 0)}};
    add_prism(b.wv_plane(), to_wv(b, p.offset_m, strip), 0, b.frame.width_m, {mat, mat, mat, mat},
              mat, b.spec.name + ".strip" + std::to_string(k + 1), b.spec.location, b.out);
  }
  return true;
}

}  // namespace dayphoton::project::detail
