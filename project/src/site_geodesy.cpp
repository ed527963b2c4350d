// DMS parsing and UTM meridian convergence with GeographicLib (Karney, "Transverse Mercator
// with an accuracy of a few nanometers", J. Geodesy 85 (2011) 475-485; GeographicLib 2.1 docs
// for DMS::Decode and UTMUPS::Forward). Sign conventions: see site_geodesy.h.
#include "dayphoton/project/site_geodesy.h"

#include <GeographicLib/DMS.hpp>
#include <GeographicLib/UTMUPS.hpp>

#include <cctype>
#include <cmath>
#include <stdexcept>

namespace dayphoton::project {

double parse_latlon_deg(const std::string& text, AngleKind kind) {
  using GeographicLib::DMS;
  DMS::flag hemisphere = DMS::NONE;
  double value = 0;
  try {
    value = DMS::Decode(text, hemisphere);
  } catch (const GeographicLib::GeographicErr& e) {
    throw std::invalid_argument(e.what());
  }
  if (kind == AngleKind::Latitude && hemisphere == DMS::LONGITUDE)
    throw std::invalid_argument("a latitude takes N or S, not E or W");
  if (kind == AngleKind::Longitude && hemisphere == DMS::LATITUDE)
    throw std::invalid_argument("a longitude takes E or W, not N or S");
  if (hemisphere == DMS::AZIMUTH)
    throw std::invalid_argument("an azimuth suffix is not a latitude or longitude");
  if (!std::isfinite(value)) throw std::invalid_argument("not a finite angle");
  return value;
}

double utm_meridian_convergence_deg(double latitude_deg, double longitude_deg, int zone) {
  if (zone < GeographicLib::UTMUPS::MINUTMZONE || zone > GeographicLib::UTMUPS::MAXUTMZONE ||
      zone == GeographicLib::UTMUPS::UPS)
    throw std::invalid_argument("UTM zone must be 1..60");
  int zone_out = 0;
  bool north_out = true;
  double x = 0, y = 0, gamma_deg = 0, scale = 0;
  try {
    GeographicLib::UTMUPS::Forward(latitude_deg, longitude_deg, zone_out, north_out, x, y,
                                   gamma_deg, scale, zone);
  } catch (const GeographicLib::GeographicErr& e) {
    throw std::invalid_argument(e.what());
  }
  return gamma_deg;
}

void parse_utm_zone(const std::string& text, int& zone, bool& north) {
  std::size_t i = 0;
  int z = 0, digits = 0;
  while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])) && digits < 3) {
    z = z * 10 + (text[i] - '0');
    ++i;
    ++digits;
  }
  while (i < text.size() && text[i] == ' ') ++i;
  const char h = i < text.size() ? static_cast<char>(std::toupper(static_cast<unsigned char>(text[i]))) : '\0';
  if (digits == 0 || i + 1 != text.size() || (h != 'N' && h != 'S'))
    throw std::invalid_argument("expected a zone number and N or S, like 33N");
  if (z < 1 || z > 60) throw std::invalid_argument("UTM zone must be 1..60");
  zone = z;
  north = h == 'N';
}

}  // namespace dayphoton::project
