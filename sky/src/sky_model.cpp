// SkyModel base behaviour: grey RADIANCE radiance, the hemisphere quadrature used for
// horizontal illuminance and for normalising skies, and RADIANCE's ground radiance.
//
// Quadrature: nested, globally adaptive Gauss-Kronrod 7/15 (the G7/K15 pair of QUADPACK,
// Piessens et al. 1983, "QUADPACK", Springer, routine QK15; the nodes and weights below are
// the published numbers). The integrand L cos(theta) sin(theta) is smooth in (theta, phi)
// except where the circumsolar term exp(d * gamma) has a cone-shaped kink at the sun; with
// breakpoints at the sun's zenith angle and azimuth the kink sits on interval ends, where
// the adaptive splitting resolves it. Error estimate per interval as QUADPACK's QK15.
//
// Ground: gendaymtx.c ComputeSky ("parr[0] = diff_illum; if (altitude > 0) parr[0] +=
// dir_illum * sin(altitude); ... *= 1/PI/WHTEFFICACY; multcolor(grefl)"), restated in
// ../shared/facts/sky-and-metrics.md §2.4 step 5 and §4.3. gensky's ground glow uses the same
// sum (sky + sun on the horizontal) times the ground reflectance over pi.
#include "dayphoton/sky/sky_model.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "dayphoton/core/units.h"

namespace dayphoton::sky {

Vec3 SkyModel::radiance_rgb(const Vec3& dir) const {
  // Grey: the same value in R, G, B; RADIANCE's RGB weights sum to 1, so
  // 179 lm/W * (0.265 + 0.670 + 0.065) * v = luminance.
  const double v = luminance_cd_m2(dir) / RadianceWhiteEfficacy_lm_per_W;
  return {v, v, v};
}

double SkyModel::horizontal_illuminance_lux() const {
  return integrate_cosine_weighted_hemisphere(
      [this](const Vec3& d) { return luminance_cd_m2(d); }, sun_direction());
}

namespace {

// Kronrod 15-point abscissae (positive half, descending) and weights; Gauss 7-point weights
// for the abscissae xgk[1], xgk[3], xgk[5], xgk[7] (QUADPACK QK15).
constexpr std::array<double, 8> Xgk = {
    0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
    0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
    0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
    0.207784955007898467600689403773245, 0.0};
constexpr std::array<double, 8> Wgk = {
    0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
    0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
    0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
    0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
constexpr std::array<double, 4> Wg = {
    0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
    0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

struct Piece {
  double a, b, value, error;
};

template <typename F>
Piece gauss_kronrod_15(const F& f, double a, double b) {
  const double centre = 0.5 * (a + b);
  const double half = 0.5 * (b - a);
  double fv[15];
  fv[7] = f(centre);
  for (int j = 0; j < 7; ++j) {
    const double dx = half * Xgk[static_cast<std::size_t>(j)];
    fv[j] = f(centre - dx);
    fv[14 - j] = f(centre + dx);
  }
  double kronrod = fv[7] * Wgk[7];
  double gauss = fv[7] * Wg[3];
  for (int j = 0; j < 7; ++j) {
    const double sum = fv[j] + fv[14 - j];
    kronrod += Wgk[static_cast<std::size_t>(j)] * sum;
    if (j % 2 == 1) gauss += Wg[static_cast<std::size_t>(j / 2)] * sum;
  }
  // QUADPACK's error estimate: |K - G| scaled by the variation of f on the interval
  // (resasc = integral of |f - mean|), err = resasc * min(1, (200 |K - G| / resasc)^1.5).
  const double mean = 0.5 * kronrod;
  double resasc = Wgk[7] * std::abs(fv[7] - mean);
  for (int j = 0; j < 7; ++j)
    resasc += Wgk[static_cast<std::size_t>(j)] * (std::abs(fv[j] - mean) + std::abs(fv[14 - j] - mean));
  double error = std::abs((kronrod - gauss) * half);
  resasc *= std::abs(half);
  if (resasc != 0 && error != 0) error = resasc * std::min(1.0, std::pow(200 * error / resasc, 1.5));
  return {a, b, kronrod * half, error};
}

/// Globally adaptive integration over the union of [breaks[i], breaks[i+1]]: split the
/// interval with the largest error estimate until the summed estimate is below abs_tol or
/// the interval budget is spent.
template <typename F>
double integrate_adaptive(const F& f, const std::vector<double>& breaks, double abs_tol,
                          int max_pieces = 400) {
  std::vector<Piece> pieces;
  pieces.reserve(static_cast<std::size_t>(max_pieces) + breaks.size());
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i)
    if (breaks[i + 1] > breaks[i]) pieces.push_back(gauss_kronrod_15(f, breaks[i], breaks[i + 1]));
  while (true) {
    double total_error = 0;
    std::size_t worst = 0;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      total_error += pieces[i].error;
      if (pieces[i].error > pieces[worst].error) worst = i;
    }
    if (pieces.empty() || total_error <= abs_tol ||
        static_cast<int>(pieces.size()) >= max_pieces)
      break;
    const Piece p = pieces[worst];
    const double mid = 0.5 * (p.a + p.b);
    if (!(mid > p.a && mid < p.b)) break;  // interval at the resolution of doubles
    pieces[worst] = gauss_kronrod_15(f, p.a, mid);
    pieces.push_back(gauss_kronrod_15(f, mid, p.b));
  }
  double total = 0;
  for (const Piece& p : pieces) total += p.value;
  return total;
}

}  // namespace

double integrate_cosine_weighted_hemisphere(const std::function<double(const Vec3&)>& f,
                                            const std::optional<Vec3>& peak,
                                            double relative_tolerance) {
  // Directions: theta = zenith angle, phi = azimuth from +Y (north) toward +X (east).
  double theta_peak = -1, phi_peak = 0;
  if (peak && is_finite(*peak) && length(*peak) > 0) {
    const Vec3 p = normalize(*peak);
    theta_peak = std::acos(std::clamp(p.z, -1.0, 1.0));
    if (p.x != 0 || p.y != 0) phi_peak = std::atan2(p.x, p.y);
  }
  std::vector<double> theta_breaks = {0.0};
  if (theta_peak > 0 && theta_peak < 0.5 * Pi) theta_breaks.push_back(theta_peak);
  theta_breaks.push_back(0.5 * Pi);
  const std::vector<double> phi_breaks = {phi_peak, phi_peak + Pi, phi_peak + 2 * Pi};

  auto inner = [&](double theta, double abs_tol, bool adaptive) {
    const double st = std::sin(theta), ct = std::cos(theta);
    auto g = [&](double phi) { return f(Vec3{st * std::sin(phi), st * std::cos(phi), ct}); };
    double v;
    if (adaptive) {
      v = integrate_adaptive(g, phi_breaks, abs_tol);
    } else {
      v = gauss_kronrod_15(g, phi_breaks[0], phi_breaks[1]).value +
          gauss_kronrod_15(g, phi_breaks[1], phi_breaks[2]).value;
    }
    return v * st * ct;
  };

  // A coarse pass sets the absolute tolerance from the size of the result.
  const double coarse =
      integrate_adaptive([&](double t) { return inner(t, 0, false); }, theta_breaks, 0, 1);
  const double scale = std::abs(coarse);
  // Our skies are non-negative and positive over large solid angles, so a zero coarse pass
  // (15 x 30 nodes) means a zero sky (night, zero diffuse).
  if (!(scale > 0)) return 0.0;
  const double abs_tol = relative_tolerance * scale;
  // The inner error is weighted by sin cos <= 1/2 over a theta range whose weight integrates
  // to 1/2, so an inner tolerance of abs_tol adds at most abs_tol / 2 to the outer error.
  return integrate_adaptive([&](double t) { return inner(t, abs_tol, true); }, theta_breaks,
                            abs_tol);
}

Vec3 ground_radiance_rgb(const Vec3& ground_reflectance_rgb, double sky_horizontal_illuminance_lux,
                         double direct_normal_illuminance_lux, const Vec3& sun_direction) {
  if (!is_finite(ground_reflectance_rgb) || ground_reflectance_rgb.x < 0 ||
      ground_reflectance_rgb.y < 0 || ground_reflectance_rgb.z < 0)
    throw std::invalid_argument("ground reflectance must be finite and non-negative");
  if (!std::isfinite(sky_horizontal_illuminance_lux) || sky_horizontal_illuminance_lux < 0 ||
      !std::isfinite(direct_normal_illuminance_lux) || direct_normal_illuminance_lux < 0)
    throw std::invalid_argument("ground illuminances must be finite and non-negative");
  if (!is_finite(sun_direction))
    throw std::invalid_argument("sun direction must be finite");
  double e_lux = sky_horizontal_illuminance_lux;
  const double len = length(sun_direction);
  // gendaymtx adds the sun only if its altitude is above 0: sin(altitude) = z / |dir|.
  if (len > 0 && sun_direction.z > 0) e_lux += direct_normal_illuminance_lux * sun_direction.z / len;
  // Lambertian ground: L = rho E / pi; RADIANCE radiance = luminance / 179 lm/W.
  const double grey = e_lux / (Pi * RadianceWhiteEfficacy_lm_per_W);
  return ground_reflectance_rgb * grey;
}

}  // namespace dayphoton::sky
