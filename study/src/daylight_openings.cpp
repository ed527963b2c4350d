#include "dayphoton/study/daylight_openings.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/units.h"
#include "dayphoton/engine/direct_component.h"
#include "dayphoton/engine/estimate_variance.h"

namespace dayphoton::study {

DaylightOpenings daylight_openings(const engine::Scene& scene) {
  DaylightOpenings out;
  const double min_vertical_component = std::cos(deg_to_rad(HorizontalOpeningMaxTilt_deg));
  for (const engine::Port& port : scene.ports().ports()) {
    const Surface& surface = scene.description().surfaces[static_cast<std::size_t>(port.surface)];
    const Vec3 n = length(surface.opening_normal) > 0 ? normalize(surface.opening_normal) : port.normal;
    if (std::abs(n.z) >= min_vertical_component) {
      out.horizontal.push_back(port.name);
      out.port_horizontal.push_back(true);
    } else {
      out.port_horizontal.push_back(false);
      out.vertical_or_inclined.push_back(port.name);
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
