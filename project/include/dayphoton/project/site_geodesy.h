// Site coordinates: DMS parsing and UTM meridian convergence (GeographicLib), used by the
// project loader for the `site` section and exposed for tests and tools.
//
// Meridian convergence, sign convention (GeographicLib, TransverseMercator docs): gamma is the
// bearing of grid north (the UTM +y axis) measured clockwise from true north. East of the
// zone's central meridian in the northern hemisphere gamma > 0: grid north points east of
// true north, so true north lies gamma degrees *counter-clockwise* of grid north.
// A model drawn in UTM coordinates has model +Y = grid north; the clockwise angle from model
// +Y to true north is therefore north_deg - gamma. The loader stores gamma in
// Site::meridian_convergence_deg; Site::rotation_to_true_north_deg() = north_deg - gamma.
#pragma once

#include <string>

namespace dayphoton::project {

enum class AngleKind { Latitude, Longitude };

/// Parse a latitude or longitude given as decimal degrees ("41.98", "-87.9") or a DMS string
/// understood by GeographicLib::DMS::Decode ("41d58'48\"N", "87d54'W", "41:58:48N").
/// A hemisphere letter must match the kind (N/S for latitude, E/W for longitude); S and W
/// make the value negative. Throws std::invalid_argument with a user-readable reason.
double parse_latlon_deg(const std::string& text, AngleKind kind);

/// Meridian convergence gamma (degrees, sign as above) at (latitude, longitude) in UTM zone
/// `zone` (1..60), from GeographicLib::UTMUPS::Forward. The hemisphere does not change gamma
/// (only the false northing), so it is not an argument. Throws std::invalid_argument if the
/// point cannot be projected in that zone.
double utm_meridian_convergence_deg(double latitude_deg, double longitude_deg, int zone);

/// Parse a zone written as "33N", "33 S", "33n" -> zone and hemisphere. Throws
/// std::invalid_argument with the reason.
void parse_utm_zone(const std::string& text, int& zone, bool& north);

}  // namespace dayphoton::project
