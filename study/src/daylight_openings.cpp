#include "dayphoton/study/daylight_openings.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/units.h"
#include "dayphoton/engine/direct_component.h"
#include "dayphoton/engine/estimate_variance.h"

namespace dayphoton::study {

namespace {

/// Union-find over ports: ports that share a vertex (to 1 micrometre) join one group.
std::vector<std::size_t> port_groups(const std::vector<engine::Port>& ports, const std::vector<bool>& grouped) {
  std::vector<std::size_t> parent(ports.size());
  for (std::size_t k = 0; k < parent.size(); ++k) parent[k] = k;
  auto find = [&](std::size_t k) {
    while (parent[k] != k) k = parent[k] = parent[parent[k]];
    return k;
  };
  std::map<std::array<long long, 3>, std::size_t> first_port_at;
  for (std::size_t k = 0; k < ports.size(); ++k) {
    if (!grouped[k]) continue;
    for (const std::array<Vec3, 3>& t : ports[k].triangles)
      for (const Vec3& v : t) {
        const std::array<long long, 3> key{std::llround(v.x * 1e6), std::llround(v.y * 1e6), std::llround(v.z * 1e6)};
        const auto [it, inserted] = first_port_at.emplace(key, k);
        if (!inserted) parent[find(k)] = find(it->second);
      }
  }
  for (std::size_t k = 0; k < parent.size(); ++k) parent[k] = find(k);
  return parent;
}

}  // namespace

DaylightOpenings daylight_openings(const engine::Scene& scene) {
  DaylightOpenings out;
  const double min_vertical_component = std::cos(deg_to_rad(HorizontalOpeningMaxTilt_deg));
  const double min_cap_facet_rise = std::sin(deg_to_rad(CapFacetMinRise_deg));
  const std::vector<engine::Port>& ports = scene.ports().ports();
  // Each port's opening plane: its own, or the one it stands for.
  std::vector<Vec3> normal(ports.size());
  std::vector<bool> own_plane(ports.size());
  for (std::size_t k = 0; k < ports.size(); ++k) {
    const Surface& surface = scene.description().surfaces[static_cast<std::size_t>(ports[k].surface)];
    own_plane[k] = !(length(surface.opening_normal) > 0);
    normal[k] = own_plane[k] ? ports[k].normal : normalize(surface.opening_normal);
  }
  // Facets that share vertices and rise from a horizontal plane (a dome, a pyramid, a ridge
  // roof light) stand for the opening they close: the sum of their vector areas is the vector
  // area of their rim, whose plane the cap's opening lies in. Each facet's normal is taken
  // pointing down, as a cap's into the room does, so that a facet whose facing the scene
  // decided the other way (ports face either way) does not cancel its neighbours.
  const std::vector<std::size_t> group = port_groups(ports, own_plane);
  std::map<std::size_t, Vec3> vector_area;
  std::map<std::size_t, int> members;
  std::map<std::size_t, bool> rises;
  for (std::size_t k = 0; k < ports.size(); ++k) {
    if (!own_plane[k]) continue;
    const Vec3 down = normal[k].z > 0 ? -normal[k] : normal[k];
    vector_area[group[k]] = vector_area[group[k]] + down * ports[k].area_m2;
    ++members[group[k]];
    const bool rising = std::abs(normal[k].z) >= min_cap_facet_rise;
    rises[group[k]] = rises.count(group[k]) ? rises[group[k]] && rising : rising;
  }
  for (std::size_t k = 0; k < ports.size(); ++k) {
    Vec3 n = normal[k];
    const std::size_t g = group[k];
    if (own_plane[k] && members[g] > 1 && rises[g] && length(vector_area[g]) > 0) n = normalize(vector_area[g]);
    if (std::abs(n.z) >= min_vertical_component) {
      out.horizontal.push_back(ports[k].name);
      out.port_horizontal.push_back(true);
    } else {
      out.port_horizontal.push_back(false);
      out.vertical_or_inclined.push_back(ports[k].name);
    }
  }
  using Openings = metrics::MetricSettings::Openings;
  out.kind = out.horizontal.empty()             ? Openings::VerticalOrInclined
             : out.vertical_or_inclined.empty() ? Openings::Horizontal
                                                : Openings::Both;
  return out;
}

namespace {

using Openings = metrics::MetricSettings::Openings;

/// The CIE standard overcast sky's luminance relative to the zenith's (Moon & Spencer 1942;
/// CIE S 011/E:2003 type 16): (1 + 2 sin(altitude)) / 3.
double overcast_relative_luminance(double sin_altitude) { return (1.0 + 2.0 * sin_altitude) / 3.0; }

/// One sensor's sky component (relative units) through horizontal and through other ports:
/// strata centres of the sky hemisphere, uniform in solid angle (sin(altitude) and azimuth
/// linear), each shadow ray weighted by the sky's luminance, the cosine at the sensor and
/// the straight transmittance on its way out (direct_component.h, trace_to_sky).
std::array<double, 2> sky_through_openings(const engine::Scene& scene, const std::vector<engine::Material>& materials,
                                           const DaylightOpenings& model, const SensorPoint& sensor) {
  std::array<double, 2> sum{0.0, 0.0};  // [0] horizontal, [1] vertical or inclined
  const double n_len = length(sensor.normal);
  if (!(n_len > 0.0)) return sum;
  const Vec3 normal = sensor.normal / n_len;
  const Vec3 origin = sensor.position + normal * scene.ray_epsilon_m();
  const int k = OpeningsViewRaysPerAxis;
  for (int i = 0; i < k; ++i) {
    const double sin_alt = (i + 0.5) / k, cos_alt = std::sqrt(1.0 - sin_alt * sin_alt);
    for (int j = 0; j < k; ++j) {
      const double az = 2.0 * Pi * (j + 0.5) / k;
      const Vec3 w{cos_alt * std::sin(az), cos_alt * std::cos(az), sin_alt};
      const double cos_theta = dot(w, normal);
      if (!(cos_theta > 0.0)) continue;
      const engine::SkyPath path = engine::trace_to_sky(scene, materials, origin, w);
      if (path.port < 0) continue;
      const double t = engine::luminance_of(path.transmittance);
      if (!(t > 0.0)) continue;
      const bool horizontal = model.port_horizontal[static_cast<std::size_t>(path.port)];
      sum[horizontal ? 0 : 1] += t * cos_theta * overcast_relative_luminance(sin_alt);
    }
  }
  return sum;
}

GridOpenings grid_openings_by_view(const engine::Scene& scene, const std::vector<engine::Material>& materials,
                                   const SensorGrid& grid, const DaylightOpenings& model) {
  GridOpenings out;
  out.by_view = true;
  const std::size_t n = grid.points.size();
  const std::size_t stride = std::max<std::size_t>(1, (n + OpeningsViewMaxSensors - 1) / OpeningsViewMaxSensors);
  const std::size_t looked = (n + stride - 1) / stride;
  std::vector<std::array<double, 2>> per_sensor(looked, {0.0, 0.0});
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, looked), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t q = r.begin(); q != r.end(); ++q)
      per_sensor[q] = sky_through_openings(scene, materials, model, grid.points[q * stride]);
  });
  double horizontal = 0.0, total = 0.0;
  for (const std::array<double, 2>& s : per_sensor) {  // in sensor order: the same sum on any threads
    horizontal += s[0];
    total += s[0] + s[1];
  }
  if (!(total > 0.0)) {
    out.kind = Openings::Both;
    return out;
  }
  out.horizontal_sky_share = horizontal / total;
  out.kind = out.horizontal_sky_share >= 1.0 - MinorOpeningsSkyShare ? Openings::Horizontal
             : out.horizontal_sky_share <= MinorOpeningsSkyShare   ? Openings::VerticalOrInclined
                                                                     : Openings::Both;
  return out;
}

std::string percent_text(double share) { return format_number(std::round(1000.0 * share) / 10.0) + " %"; }

}  // namespace

std::vector<GridOpenings> grid_daylight_openings(const engine::Scene& scene,
                                                 const std::vector<engine::Material>& materials,
                                                 const std::vector<SensorGrid>& grids,
                                                 const DaylightOpenings& model) {
  std::vector<GridOpenings> out;
  out.reserve(grids.size());
  for (const SensorGrid& grid : grids) {
    if (model.kind != Openings::Both) {
      GridOpenings g;
      g.kind = model.kind;
      out.push_back(g);
    } else {
      out.push_back(grid_openings_by_view(scene, materials, grid, model));
    }
  }
  return out;
}

void daylight_openings_diagnostics(const std::vector<SensorGrid>& grids, const DaylightOpenings& model,
                                   const std::vector<GridOpenings>& per_grid, std::vector<Diagnostic>& warnings,
                                   std::vector<Diagnostic>& notes) {
  if (model.kind != Openings::Both) return;
  const std::string rule_50 =
      "EN 17037's levels take the rule for vertical and inclined openings (the target over 50 % of the area); "
      "where the daylight comes through horizontal openings alone the standard asks the target over 95 % of the "
      "area (summary.json: the levels' target_area_percent)";
  for (std::size_t g = 0; g < grids.size() && g < per_grid.size(); ++g) {
    const GridOpenings& o = per_grid[g];
    if (!o.by_view) continue;
    Diagnostic d;
    d.location = grids[g].location;
    const std::string set = "sensor set '" + grids[g].name + "'";
    if (o.horizontal_sky_share < 0.0) {
      d.severity = Severity::Warning;
      d.message = set + " sees the sky through none of the model's openings (roof lights and windows): " + rule_50;
      warnings.push_back(d);
    } else if (o.kind == Openings::Both) {
      d.severity = Severity::Warning;
      d.message = set + " sees the sky through horizontal openings (" + percent_text(o.horizontal_sky_share) +
                  " of its sky component under the CIE overcast sky) and through vertical or inclined ones (" +
                  percent_text(1.0 - o.horizontal_sky_share) + "): " + rule_50;
      warnings.push_back(d);
    } else {
      d.severity = Severity::Note;
      const bool h = o.kind == Openings::Horizontal;
      d.message = set + " sees the sky through " + (h ? "horizontal" : "vertical and inclined") + " openings (" +
                  percent_text(h ? o.horizontal_sky_share : 1.0 - o.horizontal_sky_share) +
                  " of its sky component under the CIE overcast sky): EN 17037's target over " +
                  (h ? "95" : "50") + " % of its area";
      notes.push_back(d);
    }
  }
}

}  // namespace dayphoton::study
