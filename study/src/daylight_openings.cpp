#include "dayphoton/study/daylight_openings.h"

#include <cmath>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/units.h"

namespace dayphoton::study {

DaylightOpenings daylight_openings(const engine::Scene& scene) {
  DaylightOpenings out;
  const double min_vertical_component = std::cos(deg_to_rad(HorizontalOpeningMaxTilt_deg));
  for (const engine::Port& port : scene.ports().ports()) {
    const Surface& surface = scene.description().surfaces[static_cast<std::size_t>(port.surface)];
    const Vec3 n = length(surface.opening_normal) > 0 ? normalize(surface.opening_normal) : port.normal;
    if (std::abs(n.z) >= min_vertical_component) {
      if (out.horizontal.empty()) out.first_horizontal = port.location;
      out.horizontal.push_back(port.name);
    } else {
      out.vertical_or_inclined.push_back(port.name);
    }
  }
  using Openings = metrics::MetricSettings::Openings;
  out.kind = out.horizontal.empty()             ? Openings::VerticalOrInclined
             : out.vertical_or_inclined.empty() ? Openings::Horizontal
                                                : Openings::Both;
  return out;
}

std::optional<Diagnostic> daylight_openings_warning(const DaylightOpenings& openings) {
  if (openings.kind != metrics::MetricSettings::Openings::Both) return std::nullopt;
  const std::size_t n = openings.horizontal.size();
  Diagnostic d;
  d.severity = Severity::Warning;
  d.location = openings.first_horizontal;
  d.message = "port '" + openings.horizontal.front() + "'" +
              (n > 1 ? " and " + std::to_string(n - 1) + " more lie" : std::string(" lies")) + " within " +
              format_number(HorizontalOpeningMaxTilt_deg) +
              " degrees of horizontal, and the model also has windows: EN 17037's levels take the rule for vertical "
              "and inclined openings (the target over 50 % of the area); for a grid whose daylight comes through "
              "horizontal openings alone the standard asks the target over 95 % of the area (summary.json: the "
              "levels' target_area_percent)";
  return d;
}

}  // namespace dayphoton::study
