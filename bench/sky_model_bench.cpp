// Throughput of the sky models: radiance evaluations per second (random directions over the
// upper hemisphere, fixed seed) for the Perez all-weather sky and the CIE skies, and the cost
// of building a normalised sky (Perez: parameters + hemisphere quadrature).
// Usage: sky_model_bench [evaluations]   (default 2 000 000)
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "dayphoton/core/units.h"
#include "dayphoton/sky/perez.h"
#include "dayphoton/sky/sky_model.h"

using namespace dayphoton;
using namespace dayphoton::sky;

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

Vec3 from_altitude_azimuth(double altitude_deg, double compass_azimuth_deg) {
  const double h = deg_to_rad(altitude_deg), az = deg_to_rad(compass_azimuth_deg);
  return {std::cos(h) * std::sin(az), std::cos(h) * std::cos(az), std::sin(h)};
}

void bench_radiance(const std::string& name, const SkyModel& sky, const std::vector<Vec3>& dirs) {
  const auto t0 = Clock::now();
  Vec3 sum;
  for (const Vec3& d : dirs) sum += sky.radiance_rgb(d);
  const double s = seconds_since(t0);
  std::printf("%-34s %8.2f M radiance evaluations/s  (checksum %.6g)\n", name.c_str(),
              dirs.size() / s * 1e-6, sum.y);
}

}  // namespace

int main(int argc, char** argv) {
  const long n = argc > 1 ? std::atol(argv[1]) : 2000000;
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  std::vector<Vec3> dirs;
  dirs.reserve(static_cast<std::size_t>(n));
  for (long i = 0; i < n; ++i) {  // uniform over the hemisphere
    const double z = uni(rng), phi = 2 * Pi * uni(rng), r = std::sqrt(1 - z * z);
    dirs.push_back({r * std::cos(phi), r * std::sin(phi), z});
  }
  const Vec3 sun = from_altitude_azimuth(35, 200);

  bench_radiance("uniform", *make_uniform_sky(1000), dirs);
  bench_radiance("CIE overcast", *make_cie_overcast_sky(SkyScale::horizontal_illuminance_lux(10000)), dirs);
  for (int type : {1, 7, 12, 15})
    bench_radiance("CIE general type " + std::to_string(type),
                   *make_cie_general_sky(type, sun, SkyScale::horizontal_illuminance_lux(20000)), dirs);

  struct Case { const char* name; double dni, dhi; };
  const Case cases[] = {{"Perez I=0 Ed=150", 0, 150}, {"Perez I=300 Ed=200", 300, 200},
                        {"Perez I=850 Ed=100", 850, 100}};
  for (const Case& c : cases) {
    PerezInputs in;
    in.direct_normal_irradiance_W_m2 = c.dni;
    in.diffuse_horizontal_irradiance_W_m2 = c.dhi;
    in.sun_direction = sun;
    in.day_of_year = 172;
    const PerezSky p = make_perez_sky(in);
    bench_radiance(std::string(c.name) + ", bin " + std::to_string(p.state.bin), *p.sky, dirs);
  }

  // Building normalised skies: one per hour of a synthetic year of sun positions.
  const int builds = 2000;
  auto t0 = Clock::now();
  double checksum = 0;
  for (int i = 0; i < builds; ++i) {
    PerezInputs in;
    in.direct_normal_irradiance_W_m2 = 50.0 + (i * 37) % 800;
    in.diffuse_horizontal_irradiance_W_m2 = 20.0 + (i * 13) % 300;
    in.sun_direction = from_altitude_azimuth(2.0 + (i * 7) % 85, (i * 53) % 360);
    in.day_of_year = 1 + i % 365;
    checksum += make_perez_sky(in).relative_horizontal_integral;
  }
  double s = seconds_since(t0);
  std::printf("%-34s %8.3f ms per sky  (checksum %.6g)\n", "make_perez_sky (with quadrature)",
              s / builds * 1e3, checksum);

  t0 = Clock::now();
  checksum = 0;
  for (int i = 0; i < 200; ++i)
    checksum += make_cie_general_sky(12, from_altitude_azimuth(2.0 + (i * 7) % 85, 180),
                                     SkyScale::horizontal_illuminance_lux(1e4))
                    ->zenith_luminance_cd_m2();
  s = seconds_since(t0);
  std::printf("%-34s %8.3f ms per sky  (checksum %.6g)\n", "make_cie_general_sky type 12",
              s / 200 * 1e3, checksum);
  return 0;
}
