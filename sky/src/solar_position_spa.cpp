// NREL Solar Position Algorithm (SPA).
//
// Source: I. Reda and A. Andreas, "Solar position algorithm for solar radiation
// applications", Solar Energy 76(5) 577-589 (2004); NREL/TP-560-34302 (revised Jan 2008);
// corrigendum Solar Energy 81(6) 838 (2007). Step numbers below follow section 3 of the
// report. The periodic terms (Table A4.2: Earth heliocentric longitude L0..L5, latitude
// B0..B1, radius R0..R4) and the nutation terms (Table A4.3) are the published numbers of
// the report (Meeus' abridged VSOP87 and the IAU 1980 nutation series); they were checked
// against the table pvlib's spa.py carries. Delta T: Espenak & Meeus, "Polynomial
// expressions for Delta T", NASA Eclipse web site (2006), the polynomials pvlib uses.
// Reference values: ../shared/facts/sky-and-metrics.md section 1.3-1.4.
#include <cmath>

#include "dayphoton/core/units.h"
#include "solar_position_detail.h"

namespace dayphoton::sky {
namespace {

struct Term {
  double a, b, c;  // a * cos(b + c * JME)
};

// Table A4.2 — Earth periodic terms.
constexpr Term L0[] = {
    {175347046.0, 0.0, 0.0},        {3341656.0, 4.6692568, 6283.07585},
    {34894.0, 4.6261, 12566.1517},  {3497.0, 2.7441, 5753.3849},
    {3418.0, 2.8289, 3.5231},       {3136.0, 3.6277, 77713.7715},
    {2676.0, 4.4181, 7860.4194},    {2343.0, 6.1352, 3930.2097},
    {1324.0, 0.7425, 11506.7698},   {1273.0, 2.0371, 529.691},
    {1199.0, 1.1096, 1577.3435},    {990.0, 5.233, 5884.927},
    {902.0, 2.045, 26.298},         {857.0, 3.508, 398.149},
    {780.0, 1.179, 5223.694},       {753.0, 2.533, 5507.553},
    {505.0, 4.583, 18849.228},      {492.0, 4.205, 775.523},
    {357.0, 2.92, 0.067},           {317.0, 5.849, 11790.629},
    {284.0, 1.899, 796.298},        {271.0, 0.315, 10977.079},
    {243.0, 0.345, 5486.778},       {206.0, 4.806, 2544.314},
    {205.0, 1.869, 5573.143},       {202.0, 2.458, 6069.777},
    {156.0, 0.833, 213.299},        {132.0, 3.411, 2942.463},
    {126.0, 1.083, 20.775},         {115.0, 0.645, 0.98},
    {103.0, 0.636, 4694.003},       {102.0, 0.976, 15720.839},
    {102.0, 4.267, 7.114},          {99.0, 6.21, 2146.17},
    {98.0, 0.68, 155.42},           {86.0, 5.98, 161000.69},
    {85.0, 1.3, 6275.96},           {85.0, 3.67, 71430.7},
    {80.0, 1.81, 17260.15},         {79.0, 3.04, 12036.46},
    {75.0, 1.76, 5088.63},          {74.0, 3.5, 3154.69},
    {74.0, 4.68, 801.82},           {70.0, 0.83, 9437.76},
    {62.0, 3.98, 8827.39},          {61.0, 1.82, 7084.9},
    {57.0, 2.78, 6286.6},           {56.0, 4.39, 14143.5},
    {56.0, 3.47, 6279.55},          {52.0, 0.19, 12139.55},
    {52.0, 1.33, 1748.02},          {51.0, 0.28, 5856.48},
    {49.0, 0.49, 1194.45},          {41.0, 5.37, 8429.24},
    {41.0, 2.4, 19651.05},          {39.0, 6.17, 10447.39},
    {37.0, 6.04, 10213.29},         {37.0, 2.57, 1059.38},
    {36.0, 1.71, 2352.87},          {36.0, 1.78, 6812.77},
    {33.0, 0.59, 17789.85},         {30.0, 0.44, 83996.85},
    {30.0, 2.74, 1349.87},          {25.0, 3.16, 4690.48}};
constexpr Term L1[] = {
    {628331966747.0, 0.0, 0.0}, {206059.0, 2.678235, 6283.07585}, {4303.0, 2.6351, 12566.1517},
    {425.0, 1.59, 3.523},       {119.0, 5.796, 26.298},           {109.0, 2.966, 1577.344},
    {93.0, 2.59, 18849.23},     {72.0, 1.14, 529.69},             {68.0, 1.87, 398.15},
    {67.0, 4.41, 5507.55},      {59.0, 2.89, 5223.69},            {56.0, 2.17, 155.42},
    {45.0, 0.4, 796.3},         {36.0, 0.47, 775.52},             {29.0, 2.65, 7.11},
    {21.0, 5.34, 0.98},         {19.0, 1.85, 5486.78},            {19.0, 4.97, 213.3},
    {17.0, 2.99, 6275.96},      {16.0, 0.03, 2544.31},            {16.0, 1.43, 2146.17},
    {15.0, 1.21, 10977.08},     {12.0, 2.83, 1748.02},            {12.0, 3.26, 5088.63},
    {12.0, 5.27, 1194.45},      {12.0, 2.08, 4694.0},             {11.0, 0.77, 553.57},
    {10.0, 1.3, 6286.6},        {10.0, 4.24, 1349.87},            {9.0, 2.7, 242.73},
    {9.0, 5.64, 951.72},        {8.0, 5.3, 2352.87},              {6.0, 2.65, 9437.76},
    {6.0, 4.67, 4690.48}};
constexpr Term L2[] = {
    {52919.0, 0.0, 0.0},     {8720.0, 1.0721, 6283.0758}, {309.0, 0.867, 12566.152},
    {27.0, 0.05, 3.52},      {16.0, 5.19, 26.3},          {16.0, 3.68, 155.42},
    {10.0, 0.76, 18849.23},  {9.0, 2.06, 77713.77},       {7.0, 0.83, 775.52},
    {5.0, 4.66, 1577.34},    {4.0, 1.03, 7.11},           {4.0, 3.44, 5573.14},
    {3.0, 5.14, 796.3},      {3.0, 6.05, 5507.55},        {3.0, 1.19, 242.73},
    {3.0, 6.12, 529.69},     {3.0, 0.31, 398.15},         {3.0, 2.28, 553.57},
    {2.0, 4.38, 5223.69},    {2.0, 3.75, 0.98}};
constexpr Term L3[] = {{289.0, 5.844, 6283.076}, {35.0, 0.0, 0.0},      {17.0, 5.49, 12566.15},
                       {3.0, 5.2, 155.42},       {1.0, 4.72, 3.52},     {1.0, 5.3, 18849.23},
                       {1.0, 5.97, 242.73}};
constexpr Term L4[] = {{114.0, 3.142, 0.0}, {8.0, 4.13, 6283.08}, {1.0, 3.84, 12566.15}};
constexpr Term L5[] = {{1.0, 3.14, 0.0}};

constexpr Term B0[] = {{280.0, 3.199, 84334.662},
                       {102.0, 5.422, 5507.553},
                       {80.0, 3.88, 5223.69},
                       {44.0, 3.7, 2352.87},
                       {32.0, 4.0, 1577.34}};
constexpr Term B1[] = {{9.0, 3.9, 5507.55}, {6.0, 1.73, 5223.69}};

constexpr Term R0[] = {
    {100013989.0, 0.0, 0.0},      {1670700.0, 3.0984635, 6283.07585},
    {13956.0, 3.05525, 12566.1517}, {3084.0, 5.1985, 77713.7715},
    {1628.0, 1.1739, 5753.3849},  {1576.0, 2.8469, 7860.4194},
    {925.0, 5.453, 11506.77},     {542.0, 4.564, 3930.21},
    {472.0, 3.661, 5884.927},     {346.0, 0.964, 5507.553},
    {329.0, 5.9, 5223.694},       {307.0, 0.299, 5573.143},
    {243.0, 4.273, 11790.629},    {212.0, 5.847, 1577.344},
    {186.0, 5.022, 10977.079},    {175.0, 3.012, 18849.228},
    {110.0, 5.055, 5486.778},     {98.0, 0.89, 6069.78},
    {86.0, 5.69, 15720.84},       {86.0, 1.27, 161000.69},
    {65.0, 0.27, 17260.15},       {63.0, 0.92, 529.69},
    {57.0, 2.01, 83996.85},       {56.0, 5.24, 71430.7},
    {49.0, 3.25, 2544.31},        {47.0, 2.58, 775.52},
    {45.0, 5.54, 9437.76},        {43.0, 6.01, 6275.96},
    {39.0, 5.36, 4694.0},         {38.0, 2.39, 8827.39},
    {37.0, 0.83, 19651.05},       {37.0, 4.9, 12139.55},
    {36.0, 1.67, 12036.46},       {35.0, 1.84, 2942.46},
    {33.0, 0.24, 7084.9},         {32.0, 0.18, 5088.63},
    {32.0, 1.78, 398.15},         {28.0, 1.21, 6286.6},
    {28.0, 1.9, 6279.55},         {26.0, 4.59, 10447.39}};
constexpr Term R1[] = {{103019.0, 1.10749, 6283.07585}, {1721.0, 1.0644, 12566.1517},
                       {702.0, 3.142, 0.0},             {32.0, 1.02, 18849.23},
                       {31.0, 2.84, 5507.55},           {25.0, 1.32, 5223.69},
                       {18.0, 1.42, 1577.34},           {10.0, 5.91, 10977.08},
                       {9.0, 1.42, 6275.96},            {9.0, 0.27, 5486.78}};
constexpr Term R2[] = {{4359.0, 5.7846, 6283.0758}, {124.0, 5.579, 12566.152},
                       {12.0, 3.14, 0.0},           {9.0, 3.63, 77713.77},
                       {6.0, 1.87, 5573.14},        {3.0, 5.47, 18849.23}};
constexpr Term R3[] = {{145.0, 4.273, 6283.076}, {7.0, 3.92, 12566.15}};
constexpr Term R4[] = {{4.0, 2.56, 6283.08}};

// Table A4.3 — periodic terms for the nutation in longitude and obliquity:
// Y0..Y4 multiply X0..X4; then a, b (longitude, 0.0001") and c, d (obliquity, 0.0001").
struct NutationTerm {
  int y[5];
  double a, b, c, d;
};
constexpr NutationTerm Nutation[] = {
    {{0, 0, 0, 0, 1}, -171996, -174.2, 92025, 8.9},
    {{-2, 0, 0, 2, 2}, -13187, -1.6, 5736, -3.1},
    {{0, 0, 0, 2, 2}, -2274, -0.2, 977, -0.5},
    {{0, 0, 0, 0, 2}, 2062, 0.2, -895, 0.5},
    {{0, 1, 0, 0, 0}, 1426, -3.4, 54, -0.1},
    {{0, 0, 1, 0, 0}, 712, 0.1, -7, 0},
    {{-2, 1, 0, 2, 2}, -517, 1.2, 224, -0.6},
    {{0, 0, 0, 2, 1}, -386, -0.4, 200, 0},
    {{0, 0, 1, 2, 2}, -301, 0, 129, -0.1},
    {{-2, -1, 0, 2, 2}, 217, -0.5, -95, 0.3},
    {{-2, 0, 1, 0, 0}, -158, 0, 0, 0},
    {{-2, 0, 0, 2, 1}, 129, 0.1, -70, 0},
    {{0, 0, -1, 2, 2}, 123, 0, -53, 0},
    {{2, 0, 0, 0, 0}, 63, 0, 0, 0},
    {{0, 0, 1, 0, 1}, 63, 0.1, -33, 0},
    {{2, 0, -1, 2, 2}, -59, 0, 26, 0},
    {{0, 0, -1, 0, 1}, -58, -0.1, 32, 0},
    {{0, 0, 1, 2, 1}, -51, 0, 27, 0},
    {{-2, 0, 2, 0, 0}, 48, 0, 0, 0},
    {{0, 0, -2, 2, 1}, 46, 0, -24, 0},
    {{2, 0, 0, 2, 2}, -38, 0, 16, 0},
    {{0, 0, 2, 2, 2}, -31, 0, 13, 0},
    {{0, 0, 2, 0, 0}, 29, 0, 0, 0},
    {{-2, 0, 1, 2, 2}, 29, 0, -12, 0},
    {{0, 0, 0, 2, 0}, 26, 0, 0, 0},
    {{-2, 0, 0, 2, 0}, -22, 0, 0, 0},
    {{0, 0, -1, 2, 1}, 21, 0, -10, 0},
    {{0, 2, 0, 0, 0}, 17, -0.1, 0, 0},
    {{2, 0, -1, 0, 1}, 16, 0, -8, 0},
    {{-2, 2, 0, 2, 2}, -16, 0.1, 7, 0},
    {{0, 1, 0, 0, 1}, -15, 0, 9, 0},
    {{-2, 0, 1, 0, 1}, -13, 0, 7, 0},
    {{0, -1, 0, 0, 1}, -12, 0, 6, 0},
    {{0, 0, 2, -2, 0}, 11, 0, 0, 0},
    {{2, 0, -1, 2, 1}, -10, 0, 5, 0},
    {{2, 0, 1, 2, 2}, -8, 0, 3, 0},
    {{0, 1, 0, 2, 2}, 7, 0, -3, 0},
    {{-2, 1, 1, 0, 0}, -7, 0, 0, 0},
    {{0, -1, 0, 2, 2}, -7, 0, 3, 0},
    {{2, 0, 0, 2, 1}, -7, 0, 3, 0},
    {{2, 0, 1, 0, 0}, 6, 0, 0, 0},
    {{-2, 0, 2, 2, 2}, 6, 0, -3, 0},
    {{-2, 0, 1, 2, 1}, 6, 0, -3, 0},
    {{2, 0, -2, 0, 1}, -6, 0, 3, 0},
    {{2, 0, 0, 0, 1}, -6, 0, 3, 0},
    {{0, -1, 1, 0, 0}, 5, 0, 0, 0},
    {{-2, -1, 0, 2, 1}, -5, 0, 3, 0},
    {{-2, 0, 0, 0, 1}, -5, 0, 3, 0},
    {{0, 0, 2, 2, 1}, -5, 0, 3, 0},
    {{-2, 0, 2, 0, 1}, 4, 0, 0, 0},
    {{-2, 1, 0, 2, 1}, 4, 0, 0, 0},
    {{0, 0, 1, -2, 0}, 4, 0, 0, 0},
    {{-1, 0, 1, 0, 0}, -4, 0, 0, 0},
    {{-2, 1, 0, 0, 0}, -4, 0, 0, 0},
    {{1, 0, 0, 0, 0}, -4, 0, 0, 0},
    {{0, 0, 1, 2, 0}, 3, 0, 0, 0},
    {{0, 0, -2, 2, 2}, -3, 0, 0, 0},
    {{-1, -1, 1, 0, 0}, -3, 0, 0, 0},
    {{0, 1, 1, 0, 0}, -3, 0, 0, 0},
    {{0, -1, 1, 2, 2}, -3, 0, 0, 0},
    {{2, -1, -1, 2, 2}, -3, 0, 0, 0},
    {{0, 0, 3, 2, 2}, -3, 0, 0, 0},
    {{2, -1, 0, 2, 2}, -3, 0, 0, 0}};

template <std::size_t N>
double series(const Term (&terms)[N], double jme) {
  double sum = 0.0;
  for (const Term& t : terms) sum += t.a * std::cos(t.b + t.c * jme);
  return sum;
}

double polynomial_of_series(const double* s, int n, double jme) {
  // (S0 + S1 JME + S2 JME^2 + ...) / 1e8, Horner form.
  double v = 0.0;
  for (int i = n - 1; i >= 0; --i) v = v * jme + s[i];
  return v / 1e8;
}

double third_order(double a, double b, double c, double d, double x) {
  return ((d * x + c) * x + b) * x + a;
}

}  // namespace

double delta_t_s(double y) {
  // Espenak & Meeus (2006); t in years from the stated epoch.
  if (y >= 1800.0 && y < 1860.0) {
    const double t = y - 1800.0;
    return 13.72 - 0.332447 * t + 0.0068612 * t * t + 0.0041116 * t * t * t -
           0.00037436 * std::pow(t, 4) + 0.0000121272 * std::pow(t, 5) -
           0.0000001699 * std::pow(t, 6) + 0.000000000875 * std::pow(t, 7);
  }
  if (y >= 1860.0 && y < 1900.0) {
    const double t = y - 1860.0;
    return 7.62 + 0.5737 * t - 0.251754 * t * t + 0.01680668 * t * t * t -
           0.0004473624 * std::pow(t, 4) + std::pow(t, 5) / 233174.0;
  }
  if (y >= 1900.0 && y < 1920.0) {
    const double t = y - 1900.0;
    return -2.79 + 1.494119 * t - 0.0598939 * t * t + 0.0061966 * t * t * t -
           0.000197 * std::pow(t, 4);
  }
  if (y >= 1920.0 && y < 1941.0) {
    const double t = y - 1920.0;
    return 21.20 + 0.84493 * t - 0.076100 * t * t + 0.0020936 * t * t * t;
  }
  if (y >= 1941.0 && y < 1961.0) {
    const double t = y - 1950.0;
    return 29.07 + 0.407 * t - t * t / 233.0 + t * t * t / 2547.0;
  }
  if (y >= 1961.0 && y < 1986.0) {
    const double t = y - 1975.0;
    return 45.45 + 1.067 * t - t * t / 260.0 - t * t * t / 718.0;
  }
  if (y >= 1986.0 && y < 2005.0) {
    const double t = y - 2000.0;
    return 63.86 + 0.3345 * t - 0.060374 * t * t + 0.0017275 * t * t * t +
           0.000651814 * std::pow(t, 4) + 0.00002373599 * std::pow(t, 5);
  }
  if (y >= 2005.0 && y < 2050.0) {
    const double t = y - 2000.0;
    return 62.92 + 0.32217 * t + 0.005589 * t * t;
  }
  const double u = (y - 1820.0) / 100.0;
  if (y >= 2050.0 && y < 2150.0) return -20.0 + 32.0 * u * u - 0.5628 * (2150.0 - y);
  return -20.0 + 32.0 * u * u;
}

namespace detail {

SolarPosition spa_position(const SolarSite& site, double jd, double delta_t,
                           const SolarPositionOptions& options) {
  // 3.1 Julian day, ephemeris day, centuries and millennium.
  const double jde = jd + delta_t / 86400.0;
  const double jc = (jd - 2451545.0) / 36525.0;
  const double jce = (jde - 2451545.0) / 36525.0;
  const double jme = jce / 10.0;

  // 3.2 Earth heliocentric longitude L, latitude B (deg) and radius vector R (AU).
  const double l_terms[6] = {series(L0, jme), series(L1, jme), series(L2, jme),
                             series(L3, jme), series(L4, jme), series(L5, jme)};
  const double b_terms[2] = {series(B0, jme), series(B1, jme)};
  const double r_terms[5] = {series(R0, jme), series(R1, jme), series(R2, jme),
                             series(R3, jme), series(R4, jme)};
  const double L = wrap_360(rad_to_deg(polynomial_of_series(l_terms, 6, jme)));
  const double B = rad_to_deg(polynomial_of_series(b_terms, 2, jme));
  const double R = polynomial_of_series(r_terms, 5, jme);

  // 3.3 Geocentric longitude and latitude.
  const double theta = wrap_360(L + 180.0);
  const double beta = -B;

  // 3.4 Nutation in longitude and obliquity.
  const double x[5] = {
      third_order(297.85036, 445267.111480, -0.0019142, 1.0 / 189474.0, jce),
      third_order(357.52772, 35999.050340, -0.0001603, -1.0 / 300000.0, jce),
      third_order(134.96298, 477198.867398, 0.0086972, 1.0 / 56250.0, jce),
      third_order(93.27191, 483202.017538, -0.0036825, 1.0 / 327270.0, jce),
      third_order(125.04452, -1934.136261, 0.0020708, 1.0 / 450000.0, jce)};
  double dpsi = 0.0, deps = 0.0;
  for (const NutationTerm& n : Nutation) {
    double arg = 0.0;
    for (int j = 0; j < 5; ++j) arg += x[j] * n.y[j];
    arg = deg_to_rad(arg);
    dpsi += (n.a + n.b * jce) * std::sin(arg);
    deps += (n.c + n.d * jce) * std::cos(arg);
  }
  dpsi /= 36000000.0;
  deps /= 36000000.0;

  // 3.5 True obliquity of the ecliptic.
  const double u = jme / 10.0;
  static constexpr double eps_coeff[] = {84381.448, -4680.93, -1.55,  1999.25, -51.38, -249.67,
                                         -39.05,    7.12,     27.87,  5.79,    2.45};
  double eps0 = 0.0;
  for (int i = 10; i >= 0; --i) eps0 = eps0 * u + eps_coeff[i];
  const double eps = eps0 / 3600.0 + deps;

  // 3.6-3.7 Aberration correction and apparent sun longitude.
  const double dtau = -20.4898 / (3600.0 * R);
  const double lambda = theta + dpsi + dtau;

  // 3.8 Apparent sidereal time at Greenwich.
  const double nu0 = wrap_360(280.46061837 + 360.98564736629 * (jd - 2451545.0) +
                              0.000387933 * jc * jc - jc * jc * jc / 38710000.0);
  const double nu = nu0 + dpsi * std::cos(deg_to_rad(eps));

  // 3.9-3.10 Geocentric right ascension and declination.
  const double lam_r = deg_to_rad(lambda), eps_r = deg_to_rad(eps), beta_r = deg_to_rad(beta);
  const double alpha = wrap_360(rad_to_deg(
      std::atan2(std::sin(lam_r) * std::cos(eps_r) - std::tan(beta_r) * std::sin(eps_r),
                 std::cos(lam_r))));
  const double delta = std::asin(std::sin(beta_r) * std::cos(eps_r) +
                                 std::cos(beta_r) * std::sin(eps_r) * std::sin(lam_r));

  // 3.11 Observer local hour angle.
  const double H = wrap_360(nu + site.longitude_deg - alpha);

  // 3.12 Topocentric right ascension (parallax).
  const double phi = deg_to_rad(site.latitude_deg);
  const double xi = deg_to_rad(8.794 / (3600.0 * R));
  const double uu = std::atan(0.99664719 * std::tan(phi));
  const double xx = std::cos(uu) + site.elevation_m / 6378140.0 * std::cos(phi);
  const double yy = 0.99664719 * std::sin(uu) + site.elevation_m / 6378140.0 * std::sin(phi);
  const double H_r = deg_to_rad(H);
  const double dalpha = std::atan2(-xx * std::sin(xi) * std::sin(H_r),
                                   std::cos(delta) - xx * std::sin(xi) * std::cos(H_r));
  const double delta_p = std::atan2((std::sin(delta) - yy * std::sin(xi)) * std::cos(dalpha),
                                    std::cos(delta) - xx * std::sin(xi) * std::cos(H_r));

  // 3.13 Topocentric local hour angle.
  const double Hp = H_r - dalpha;

  // 3.14 Topocentric elevation, refraction.
  const double e0 = rad_to_deg(std::asin(std::sin(phi) * std::sin(delta_p) +
                                         std::cos(phi) * std::cos(delta_p) * std::cos(Hp)));
  double de = 0.0;
  if (options.apply_refraction && e0 >= -(0.26667 + options.horizon_refraction_deg)) {
    de = site.pressure_mbar / 1010.0 * 283.0 / (273.0 + site.temperature_c) * 1.02 /
         (60.0 * std::tan(deg_to_rad(e0 + 10.3 / (e0 + 5.11))));
  }

  // 3.15-3.16 Topocentric azimuth, astronomers' (from south, westward) then from north.
  const double gamma = rad_to_deg(
      std::atan2(std::sin(Hp), std::cos(Hp) * std::sin(phi) - std::tan(delta_p) * std::cos(phi)));

  SolarPosition p;
  p.true_altitude_rad = deg_to_rad(e0);
  p.altitude_rad = deg_to_rad(e0 + de);
  p.azimuth_rad = deg_to_rad(wrap_360(gamma + 180.0));
  p.declination_rad = delta;
  p.hour_angle_rad = std::remainder(H_r, 2.0 * Pi);
  finish_position(p);
  return p;
}

}  // namespace detail
}  // namespace dayphoton::sky
