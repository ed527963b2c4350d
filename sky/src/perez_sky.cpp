// Perez all-weather sky luminance distribution with the Perez 1990 luminous efficacies.
//
// What it models: the relative luminance of the sky (no sun disc) for one time step,
//   lv(zeta, gamma) = [1 + a exp(b / cos zeta)] [1 + c exp(d gamma) + e cos^2 gamma],
// scaled so that the sky's horizontal illuminance equals E_d * eta_diffuse.
//
// Sources (numbers are the published ones, restated in ../shared/facts/sky-and-metrics.md §2):
//  - Perez, Seals & Michalsky 1993, Solar Energy 50(3):235-245, eq. 1 and Table 1 (a..e
//    coefficients, with the erratum, Solar Energy 51(5):423); bin 1 special forms of c and d.
//  - Perez, Ineichen, Seals, Michalsky & Stewart 1990, Solar Energy 44(5):271-289: sky
//    clearness (eq. 1), brightness (eq. 2), precipitable water (eq. 3), clearness bins
//    (Table 1), global/diffuse/direct efficacies (Table 4; eqs. 6-8).
//  - Kasten 1966 relative air mass; Sen 2008 eccentricity series (as gendaymtx.c).
//  - RADIANCE gendaymtx.c (LBNL-ETA/Radiance 2025) for the clamps and edge cases (facts §2.6).
//
// Parameters (PerezInputs, perez.h): direct normal irradiance I (W/m^2), diffuse horizontal
// irradiance E_d (W/m^2), sun direction (unit vector), day of year J (1..366), dew point T_d
// (deg C, default 11 as NREL gendaymtx).
//
// RADIANCE rules applied (gendaymtx): Z := 90 deg if the sun altitude <= 0, Z := 3 deg if >= 87
// deg, and the circumsolar geometry uses that Z with the sun's azimuth; night if I + E_d <=
// 1e-4; epsilon clamped to [1, 11.9]; Delta clamped to [0.01, 0.6]; Delta raised to 0.2 for the
// luminance parameters (not the efficacies) when 1.065 < epsilon < 2.8; lv < 0 clamped to 0;
// if lv integrates to ~0 the sky is uniform. Our own decisions (docs/sky-models.md): the sky is
// the continuous function normalised by quadrature (gendaymtx normalises over its patch
// centres); b > 0, for which the continuous function diverges at the horizon (gendaylit
// refuses such skies), is set to 0 and reported.
#include "dayphoton/sky/perez.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include "dayphoton/core/units.h"

namespace dayphoton::sky {
namespace {

constexpr double SolarConstant_W_m2 = 1367.0;  // gendaymtx DC_SolarConstantE
constexpr double ClearnessKappa = 1.041;        // Perez 1990 eq. 1, Z in radians
constexpr double EpsilonMax = 11.9;             // gendaymtx clamp for irradiance input
constexpr double DeltaMin = 0.01, DeltaMax = 0.6;
constexpr double NightThreshold_W_m2 = 1e-4;    // gendaymtx "effectively nighttime"

// Perez 1990 Table 1 clearness bin upper bounds (bin 8 upper bound as RADIANCE).
constexpr double BinUpper[8] = {1.065, 1.230, 1.500, 1.950, 2.800, 4.500, 6.200, 12.01};

// Perez 1993 Table 1 (with erratum): per bin a1..a4, b1..b4, c1..c4, d1..d4, e1..e4.
constexpr double PerezCoefficients[8][20] = {
    {1.3525, -0.2576, -0.2690, -1.4366, -0.7670, 0.0007, 1.2734, -0.1233, 2.8000, 0.6004,
     1.2375, 1.0000, 1.8734, 0.6297, 0.9738, 0.2809, 0.0356, -0.1246, -0.5718, 0.9938},
    {-1.2219, -0.7730, 1.4148, 1.1016, -0.2054, 0.0367, -3.9128, 0.9156, 6.9750, 0.1774,
     6.4477, -0.1239, -1.5798, -0.5081, -1.7812, 0.1080, 0.2624, 0.0672, -0.2190, -0.4285},
    {-1.1000, -0.2515, 0.8952, 0.0156, 0.2782, -0.1812, -4.5000, 1.1766, 24.7219, -13.0812,
     -37.7000, 34.8438, -5.0000, 1.5218, 3.9229, -2.6204, -0.0156, 0.1597, 0.4199, -0.5562},
    {-0.5484, -0.6654, -0.2672, 0.7117, 0.7234, -0.6219, -5.6812, 2.6297, 33.3389, -18.3000,
     -62.2500, 52.0781, -3.5000, 0.0016, 1.1477, 0.1062, 0.4659, -0.3296, -0.0876, -0.0329},
    {-0.6000, -0.3566, -2.5000, 2.3250, 0.2937, 0.0496, -5.6812, 1.8415, 21.0000, -4.7656,
     -21.5906, 7.2492, -3.5000, -0.1554, 1.4062, 0.3988, 0.0032, 0.0766, -0.0656, -0.1294},
    {-1.0156, -0.3670, 1.0078, 1.4051, 0.2875, -0.5328, -3.8500, 3.3750, 14.0000, -0.9999,
     -7.1406, 7.5469, -3.4000, -0.1078, -1.0750, 1.5702, -0.0672, 0.4016, 0.3017, -0.4844},
    {-1.0000, 0.0211, 0.5025, -0.5119, -0.3000, 0.1922, 0.7023, -1.6317, 19.0000, -5.0000,
     1.2438, -1.9094, -4.0000, 0.0250, 0.3844, 0.2656, 1.0468, -0.3788, -2.4517, 1.4656},
    {-1.0500, 0.0289, 0.4260, 0.3590, -0.3250, 0.1156, 0.7781, 0.0025, 31.0625, -14.5000,
     -46.1148, 55.3750, -7.2312, 0.4050, 13.3500, 0.6234, 1.5000, -0.6426, 1.8564, 0.5636},
};

// Perez 1990 Table 4 efficacy coefficients a, b, c, d per bin (facts §2.5, as gendaymtx).
struct EfficacyCoefficients {
  double a, b, c, d;
};
constexpr EfficacyCoefficients GlobalEfficacy[8] = {
    {96.63, -0.47, 11.50, -9.16}, {107.54, 0.79, 1.79, -1.19}, {98.73, 0.70, 4.40, -6.95},
    {92.72, 0.56, 8.36, -8.31},   {86.73, 0.98, 7.10, -10.94}, {88.34, 1.39, 6.06, -7.60},
    {78.63, 1.47, 4.93, -11.37},  {99.65, 1.86, -4.46, -3.15}};
constexpr EfficacyCoefficients DiffuseEfficacy[8] = {
    {97.24, -0.46, 12.00, -8.91},   {107.22, 1.15, 0.59, -3.95},  {104.97, 2.96, -5.53, -8.77},
    {102.39, 5.59, -13.95, -13.90}, {100.71, 5.94, -22.75, -23.74}, {106.42, 3.83, -36.15, -28.83},
    {141.88, 1.90, -53.24, -14.03}, {152.23, 0.35, -45.27, -7.98}};
constexpr EfficacyCoefficients DirectEfficacy[8] = {
    {57.20, -4.55, -2.98, 117.12}, {98.99, -3.46, -1.21, 12.38}, {109.83, -4.90, -1.71, -8.81},
    {110.34, -5.84, -1.99, -4.56}, {106.36, -3.97, -1.75, -6.16}, {107.19, -1.25, -1.51, -26.73},
    {105.75, 0.77, -1.26, -34.44}, {101.18, 1.58, -1.10, -8.29}};

const EfficacyCoefficients& efficacy_row(const EfficacyCoefficients (&table)[8], int bin) {
  if (bin < 1 || bin > 8) throw std::invalid_argument("Perez clearness bin must be 1..8");
  return table[bin - 1];
}

/// Kasten 1966 relative air mass, Z in radians (the formula takes degrees in its correction).
double kasten_air_mass(double zenith_rad) {
  return 1.0 / (std::cos(zenith_rad) + 0.15 * std::pow(93.885 - rad_to_deg(zenith_rad), -1.253));
}

/// Eccentricity correction E0 (Sen 2008 p. 72, as gendaymtx), day angle from day of year.
double eccentricity(int day_of_year) {
  const double g = 2.0 * Pi * (day_of_year - 1.0) / 365.0;
  return 1.00011 + 0.034221 * std::cos(g) + 0.00128 * std::sin(g) + 0.000719 * std::cos(2 * g) +
         0.000077 * std::sin(2 * g);
}

class PerezSkyModel final : public SkyModel {
 public:
  PerezSkyModel(const PerezState& s, double scale_cd_m2, bool uniform)
      : m_state(s), m_scale_cd_m2(scale_cd_m2), m_uniform(uniform) {}

  double luminance_cd_m2(const Vec3& dir) const override {
    if (!(dir.z > 0) || m_scale_cd_m2 == 0) return 0.0;
    if (m_uniform) return m_scale_cd_m2;
    const double cos_gamma = std::clamp(dot(dir, m_state.model_sun_direction), -1.0, 1.0);
    return m_scale_cd_m2 * relative(dir.z, std::acos(cos_gamma), cos_gamma);
  }
  std::optional<Vec3> sun_direction() const override {
    if (m_uniform) return std::nullopt;
    return m_state.model_sun_direction;
  }
  std::string description() const override {
    std::ostringstream s;
    const PerezState& p = m_state;
    s << "Perez all-weather sky (1993) with Perez 1990 efficacies: sun altitude "
      << rad_to_deg(p.sun_altitude_rad) << " deg (model zenith " << rad_to_deg(p.sun_zenith_rad)
      << " deg), epsilon " << p.epsilon << ", delta " << p.delta << ", bin " << p.bin
      << ", a=" << p.a << " b=" << p.b << " c=" << p.c << " d=" << p.d << " e=" << p.e
      << ", diffuse horizontal illuminance " << p.diffuse_horizontal_illuminance_lux << " lx";
    if (p.night) s << " (night: zero sky)";
    if (m_uniform) s << " (relative luminance integrated to zero: uniform sky)";
    return s.str();
  }

  /// lv for cos(zeta) > 0, clamped at 0.
  double relative(double cos_zeta, double gamma, double cos_gamma) const {
    const PerezState& p = m_state;
    const double gradation = 1.0 + p.a * std::exp(p.b / cos_zeta);
    const double indicatrix = 1.0 + p.c * std::exp(p.d * gamma) + p.e * cos_gamma * cos_gamma;
    return std::max(0.0, gradation * indicatrix);
  }

 private:
  PerezState m_state;
  double m_scale_cd_m2;  ///< cd/m^2 per unit of lv (or the uniform luminance)
  bool m_uniform;
};

}  // namespace

int perez_clearness_bin(double epsilon) {
  for (int i = 0; i < 8; ++i)
    if (epsilon < BinUpper[i]) return i + 1;
  return 8;  // beyond RADIANCE's 12.01: the open-ended clear bin of the paper
}

double perez_global_efficacy_lm_W(int bin, double water_cm, double zenith_rad, double delta) {
  const EfficacyCoefficients& k = efficacy_row(GlobalEfficacy, bin);
  return k.a + k.b * water_cm + k.c * std::cos(zenith_rad) + k.d * std::log(delta);
}

double perez_diffuse_efficacy_lm_W(int bin, double water_cm, double zenith_rad, double delta) {
  const EfficacyCoefficients& k = efficacy_row(DiffuseEfficacy, bin);
  return k.a + k.b * water_cm + k.c * std::cos(zenith_rad) + k.d * std::log(delta);
}

double perez_direct_efficacy_lm_W(int bin, double water_cm, double zenith_rad, double delta) {
  const EfficacyCoefficients& k = efficacy_row(DirectEfficacy, bin);
  return std::max(0.0, k.a + k.b * water_cm + k.c * std::exp(5.73 * zenith_rad - 5.0) + k.d * delta);
}

PerezState perez_state(const PerezInputs& in) {
  const double dni = in.direct_normal_irradiance_W_m2;
  const double dhi = in.diffuse_horizontal_irradiance_W_m2;
  if (!std::isfinite(dni) || dni < 0 || !std::isfinite(dhi) || dhi < 0)
    throw std::invalid_argument("Perez sky: irradiances must be finite and >= 0 W/m2");
  if (!is_finite(in.sun_direction) || std::abs(length(in.sun_direction) - 1.0) > 1e-6)
    throw std::invalid_argument("Perez sky: the sun direction must be a unit vector");
  if (in.day_of_year < 1 || in.day_of_year > 366)
    throw std::invalid_argument("Perez sky: day of year must be 1..366, got " +
                                std::to_string(in.day_of_year));
  if (in.dew_point_C && !std::isfinite(*in.dew_point_C))
    throw std::invalid_argument("Perez sky: the dew point must be finite");

  PerezState s;
  const Vec3& sun = in.sun_direction;
  s.sun_altitude_rad = std::asin(std::clamp(sun.z, -1.0, 1.0));

  // gendaymtx ComputeSky: keep the sun off the horizon and the circumsolar peak off the zenith.
  if (s.sun_altitude_rad <= 0) {
    s.sun_zenith_rad = 0.5 * Pi;
    s.sun_zenith_clamped = true;
  } else if (s.sun_altitude_rad >= deg_to_rad(87.0)) {
    s.sun_zenith_rad = deg_to_rad(3.0);
    s.sun_zenith_clamped = true;
  } else {
    s.sun_zenith_rad = 0.5 * Pi - s.sun_altitude_rad;
  }
  // Same azimuth at the model zenith angle (a sun exactly at the zenith is put due south,
  // RADIANCE azimuth 0).
  const double horizontal = std::hypot(sun.x, sun.y);
  const double hx = horizontal > 0 ? sun.x / horizontal : 0.0;
  const double hy = horizontal > 0 ? sun.y / horizontal : -1.0;
  s.model_sun_direction = Vec3{hx * std::sin(s.sun_zenith_rad), hy * std::sin(s.sun_zenith_rad),
                               std::cos(s.sun_zenith_rad)};
  s.sun_below_horizon_with_direct = s.sun_altitude_rad <= 0 && dni > GendaymtxBelowHorizonWarning_W_m2;

  s.dew_point_defaulted = !in.dew_point_C.has_value();
  s.dew_point_C = in.dew_point_C.value_or(PerezDefaultDewPoint_C);
  s.precipitable_water_cm = std::exp(0.07 * s.dew_point_C - 0.075);  // Perez 1990 eq. 3
  s.air_mass = kasten_air_mass(s.sun_zenith_rad);
  s.eccentricity = eccentricity(in.day_of_year);

  s.night = dni + dhi <= NightThreshold_W_m2;
  if (s.night) return s;  // zero sky; nothing else is defined

  // Sky clearness (Perez 1990 eq. 1); E_d = 0 gives infinity, clamped below.
  const double z3 = s.sun_zenith_rad * s.sun_zenith_rad * s.sun_zenith_rad;
  s.epsilon_unclamped = dhi > 0 ? ((dhi + dni) / dhi + ClearnessKappa * z3) / (1.0 + ClearnessKappa * z3)
                                : std::numeric_limits<double>::infinity();
  s.epsilon = std::clamp(s.epsilon_unclamped, 1.0, EpsilonMax);
  s.epsilon_clamped = s.epsilon != s.epsilon_unclamped;
  // Sky brightness (eq. 2).
  s.delta_unclamped = dhi * s.air_mass / (SolarConstant_W_m2 * s.eccentricity);
  s.delta = std::clamp(s.delta_unclamped, DeltaMin, DeltaMax);
  s.delta_clamped = s.delta != s.delta_unclamped;
  s.bin = perez_clearness_bin(s.epsilon);

  s.diffuse_efficacy_lm_W =
      perez_diffuse_efficacy_lm_W(s.bin, s.precipitable_water_cm, s.sun_zenith_rad, s.delta);
  s.direct_efficacy_lm_W =
      perez_direct_efficacy_lm_W(s.bin, s.precipitable_water_cm, s.sun_zenith_rad, s.delta);
  s.diffuse_horizontal_illuminance_lux = dhi * s.diffuse_efficacy_lm_W;
  s.direct_normal_illuminance_lux = dni * s.direct_efficacy_lm_W;

  // Luminance parameters (Perez 1993 eqs. 6-8 as gendaymtx CalcPerezParam).
  s.delta_luminance = s.delta;
  if (s.epsilon > 1.065 && s.epsilon < 2.8 && s.delta_luminance < 0.2) {
    s.delta_luminance = 0.2;
    s.delta_raised_to_0_2 = true;
  }
  const double* x = PerezCoefficients[s.bin - 1];
  const double z = s.sun_zenith_rad, dl = s.delta_luminance;
  auto linear = [&](int i) { return x[4 * i] + x[4 * i + 1] * z + dl * (x[4 * i + 2] + x[4 * i + 3] * z); };
  s.a = linear(0);
  s.b = linear(1);
  s.e = linear(4);
  if (s.bin == 1) {
    s.c = std::exp(std::pow(dl * (x[8] + x[9] * z), x[10])) - x[11];
    s.d = -std::exp(dl * (x[12] + x[13] * z)) + x[14] + dl * x[15];
  } else {
    s.c = linear(2);
    s.d = linear(3);
  }
  if (s.b > 0) {
    s.b = 0;
    s.b_positive_clamped = true;
  }
  return s;
}

double perez_relative_luminance(const PerezState& s, double zeta_rad, double gamma_rad) {
  const double cos_zeta = std::cos(zeta_rad);
  if (!(cos_zeta > 0)) return 0.0;
  const double cos_gamma = std::cos(gamma_rad);
  const double gradation = 1.0 + s.a * std::exp(s.b / cos_zeta);
  const double indicatrix = 1.0 + s.c * std::exp(s.d * gamma_rad) + s.e * cos_gamma * cos_gamma;
  return std::max(0.0, gradation * indicatrix);
}

PerezSky make_perez_sky(const PerezInputs& inputs) {
  PerezSky out;
  out.state = perez_state(inputs);
  const PerezState& s = out.state;
  if (s.night) {
    out.sky = std::make_unique<PerezSkyModel>(s, 0.0, false);
    return out;
  }
  const PerezSkyModel shape(s, 1.0, false);
  double integral = integrate_cosine_weighted_hemisphere(
      [&shape](const Vec3& d) { return shape.luminance_cd_m2(d); }, s.model_sun_direction);
  // gendaymtx: "Check for zero sky -- make uniform in that case" (FTINY = 1e-6).
  if (integral <= 1e-6) {
    out.uniform_fallback = true;
    integral = Pi;
  }
  out.relative_horizontal_integral = integral;
  out.sky = std::make_unique<PerezSkyModel>(s, s.diffuse_horizontal_illuminance_lux / integral,
                                            out.uniform_fallback);
  return out;
}

}  // namespace dayphoton::sky
