// The kind of a model's daylight openings, for EN 17037:2018's daylight provision.
//
// EN 17037 (Annex A, Table A.1) asks, for a level, the target illuminance over 50 % of the
// reference plane and the minimum target over 95 % when the daylight comes through openings
// in vertical and inclined surfaces (windows, roof windows in a pitched roof), and the target
// over 95 % when it comes through horizontal openings (roof lights in a flat roof), whose
// light is spread more evenly. A roof-lit hall assessed with the 50 % rule can pass a level
// the standard does not give it.
//
// Each port counts by the plane of the opening it stands for: its own, the window's for the
// box of openings around a window's exterior system (Surface::opening_normal), the roof's
// for a light pipe's collector, or, for facets that share vertices and all rise from the
// vertical (a dome, a pyramid or a ridge roof light drawn as polygons or imported), the plane
// of their rim: the sum of their vector areas is the rim's vector area. A plane
// within HorizontalOpeningMaxTilt_deg of horizontal is horizontal: the standard draws no
// line; roof glazing laid to falls (a few degrees) is horizontal in any reading, a roof window
// in a pitched roof of 20 degrees or more is inclined.
//
// A model with both kinds (side-lit offices beside a roof-lit hall) is decided per sensor set
// (grid_daylight_openings): by the openings through which the set sees the sky. Its sky
// component under the CIE standard overcast sky (the daylight factor's sky) is split by the
// port each shadow ray leaves through (direct_component.h, the shadow-ray rule); a kind that
// gives at least MinorOpeningsSkyShare of it counts. Horizontal openings alone: the 95 %
// rule; vertical and inclined alone: the 50 % rule; both: the 50 % rule with a located
// warning at the set. A set that sees the sky through no opening (lit through a light pipe's
// diffuser or by reflected light only) keeps the 50 % rule with a warning too. This reading of
// the standard, which names the openings of a space but not a mix of them, is ours.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/core/scene_description.h"
#include "dayphoton/core/source_location.h"
#include "dayphoton/engine/material.h"
#include "dayphoton/engine/scene.h"
#include "dayphoton/metrics/annual_metrics.h"

namespace dayphoton::study {

/// The largest tilt from horizontal (degrees) of a horizontal daylight opening.
constexpr double HorizontalOpeningMaxTilt_deg = 15.0;

/// The least rise from vertical (degrees) of every facet of a cap of glazing (ports sharing
/// vertices) counted by its rim: a faceted dome's lowest ring rises a few degrees, a
/// conservatory's wall glazing joined to its roof glazing not at all (each pane then counts
/// by its own plane).
constexpr double CapFacetMinRise_deg = 1.0;

struct DaylightOpenings {
  metrics::MetricSettings::Openings kind = metrics::MetricSettings::Openings::VerticalOrInclined;
  std::vector<std::string> horizontal;  ///< the horizontal ports' names, in port order
  std::vector<std::string> vertical_or_inclined;
  std::vector<bool> port_horizontal;    ///< per port of the scene, in port order
};

DaylightOpenings daylight_openings(const engine::Scene& scene);

/// The smallest share of a sensor set's sky component through one kind of opening that makes
/// that kind count for the set: a glimpse of a roof light from a side-lit room does not
/// change the room's rule.
constexpr double MinorOpeningsSkyShare = 0.1;

/// Sensors of a set whose sky is looked at (every k-th, k the smallest that keeps the count
/// at most this), and shadow rays per sensor (strata of the sky hemisphere, a square).
constexpr std::size_t OpeningsViewMaxSensors = 1024;
constexpr int OpeningsViewRaysPerAxis = 16;

struct GridOpenings {
  metrics::MetricSettings::Openings kind = metrics::MetricSettings::Openings::VerticalOrInclined;
  /// Decided by the set's view of the sky (a model with both kinds); false: the model's kind.
  bool by_view = false;
  /// By view: the set's sky component through horizontal openings as a share of that through
  /// every opening (0-1); negative when the set sees the sky through no opening.
  double horizontal_sky_share = -1.0;
};

/// EN 17037's openings of each sensor set: the model's kind for every set, or, when the model
/// has both kinds, each set's by its view of the sky (header comment). Deterministic (strata
/// centres, sums in sensor order), any thread count.
std::vector<GridOpenings> grid_daylight_openings(const engine::Scene& scene,
                                                 const std::vector<engine::Material>& materials,
                                                 const std::vector<SensorGrid>& grids,
                                                 const DaylightOpenings& model);

/// The located warnings for sets whose rule the view left undecided (both kinds, or no sky
/// seen), at each set, and a note per set decided by view; none for a model of one kind.
void daylight_openings_diagnostics(const std::vector<SensorGrid>& grids, const DaylightOpenings& model,
                                   const std::vector<GridOpenings>& per_grid, std::vector<Diagnostic>& warnings,
                                   std::vector<Diagnostic>& notes);

}  // namespace dayphoton::study
