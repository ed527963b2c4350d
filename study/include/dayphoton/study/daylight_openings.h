// The kind of a model's daylight openings, for EN 17037:2018's daylight provision.
//
// EN 17037 (Annex A, Table A.1) asks, for a level, the target illuminance over 50 % of the
// reference plane and the minimum target over 95 % when the daylight comes through openings
// in vertical and inclined surfaces (windows, roof windows in a pitched roof), and the target
// over 95 % when it comes through horizontal openings (roof lights in a flat roof), whose
// light is spread more evenly. A roof-lit hall assessed with the 50 % rule can pass a level
// the standard does not give it.
//
// Each port counts by the plane of the opening it stands for: its own, or the window's for
// the box of openings around a window's exterior system (Surface::opening_normal). A plane
// within HorizontalOpeningMaxTilt_deg of horizontal is horizontal: the standard draws no
// line; roof glazing laid to falls (a few degrees) is horizontal in any reading, a roof window
// in a pitched roof of 20 degrees or more is inclined.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/source_location.h"
#include "dayphoton/engine/scene.h"
#include "dayphoton/metrics/annual_metrics.h"

namespace dayphoton::study {

/// The largest tilt from horizontal (degrees) of a horizontal daylight opening.
constexpr double HorizontalOpeningMaxTilt_deg = 15.0;

struct DaylightOpenings {
  metrics::MetricSettings::Openings kind = metrics::MetricSettings::Openings::VerticalOrInclined;
  std::vector<std::string> horizontal;  ///< the horizontal ports' names, in port order
  std::vector<std::string> vertical_or_inclined;
  SourceLocation first_horizontal;      ///< where the first horizontal port is written
};

DaylightOpenings daylight_openings(const engine::Scene& scene);

/// With openings of both kinds: a located warning (at the first horizontal one) that the
/// levels take the rule for vertical and inclined openings, and what the standard asks where
/// a grid's daylight comes through the horizontal ones alone. None otherwise.
std::optional<Diagnostic> daylight_openings_warning(const DaylightOpenings& openings);

}  // namespace dayphoton::study
