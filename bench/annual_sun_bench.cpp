// annual_sun_bench: the sun-bins mode of the office study (projects/office) against a
// reference that traces the hourly suns EXACTLY, direct and indirect (issue 6 acceptance
// "annual sun"; docs/sun.md). Both use the same sky coefficients, the same sky-only matrix
// and the same exact direct sun, so every difference comes from the indirect sun: the
// interpolation between sun bins plus the photon noise of both sides. A second exact
// reference with other seeds measures that noise floor.
//
// Reported, over the compared hours (every `stride`-th sun hour; stride 1 = the whole year):
//   - per sensor, the relative difference of the summed illuminance over the compared hours;
//     RMS over sensors and the largest;
//   - per sensor, the hourly RMS difference relative to the sensor's mean illuminance;
//   - the same for the indirect sun alone;
//   - DA300, UDI 100-2000 and mean occupied illuminance per sensor over the occupied
//     compared hours (stride 1: over the whole year's 3650 occupied hours, night included);
//   - the nearest-bin (no interpolation) variant, to show what the interpolation buys.
// Also timed: sun-bin tracing, estimates, exact direct sun for all hours.
//
// Usage: annual_sun_bench [stride=1] [sun photon fraction=SunBinPhotonFraction]
//                         [sun bandwidth=study::sun_bin_bandwidth(project bandwidth)] [threads]
//                         [reference photon factor=1] [sun_mf=project's]   (0 = the default)
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "dayphoton/core/units.h"
#include "dayphoton/engine/daylight_coefficients.h"
#include "dayphoton/engine/photon_tracer.h"
#include "dayphoton/engine/port_emission.h"
#include "dayphoton/engine/scene.h"
#include "dayphoton/engine/sun_bins.h"
#include "dayphoton/metrics/annual_metrics.h"
#include "dayphoton/metrics/occupancy.h"
#include "dayphoton/project/project.h"
#include "dayphoton/study/annual_illuminance.h"
#include "dayphoton/study/annual_sun.h"
#include "dayphoton/study/sun_site.h"
#include "dayphoton/weather/epw_reader.h"

using namespace dayphoton;
using Clock = std::chrono::steady_clock;

namespace {

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// Photon coefficients (sensors x suns x RGB) of exact sun discs, traced in chunks so the
/// photons of thousands of suns never sit in memory together. Chunk c uses seed + c.
RadianceMatrix exact_sun_coefficients(const engine::Scene& scene, const std::vector<engine::Material>& materials,
                                      const engine::ReceiverPlane& plane, const std::vector<SensorPoint>& sensors,
                                      const std::vector<sky::SunRecord>& suns, engine::TracingOptions tracing,
                                      const engine::CoefficientOptions& estimating, double minimum_bound,
                                      std::uint64_t seed) {
  constexpr std::size_t Chunk = 256;
  RadianceMatrix out(sensors.size(), suns.size(), 3);
  for (std::size_t first = 0; first < suns.size(); first += Chunk) {
    const std::size_t n = std::min(Chunk, suns.size() - first);
    engine::SourceSet discs;
    for (std::size_t i = 0; i < n; ++i) discs.add_sun_disc(suns[first + i].direction, sky::SunHalfAngle_rad);
    tracing.seed = seed + first / Chunk;
    // The sun-bin rule (study::SunBinMinimumBoundFraction) with the bins' largest bound.
    const engine::PortEmitter emitter(scene, discs);
    std::vector<engine::TracedPhotons> per_sun(n);
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t p) {
      if (emitter.bound_flux(p) >= minimum_bound && emitter.bound_flux(p) > 0) {
        per_sun[p] = engine::trace_source_photons(scene, materials, emitter, {plane}, tracing, p);
      } else {
        per_sun[p].planes.resize(1);
        per_sun[p].tallies.resize(1);
      }
    });
    const engine::TracedPhotons traced = engine::merge_traced_photons(std::move(per_sun));
    const engine::GridPhotons gp = engine::GridPhotons::for_plane(plane, traced.planes[0], n);
    const RadianceMatrix c = study::sun_bin_coefficients(scene, materials, discs, gp, sensors, estimating);
    for (std::size_t s = 0; s < sensors.size(); ++s)
      for (std::size_t i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k) out.at(s, first + i, k) = c.at(s, i, k);
  }
  return out;
}

/// Indirect lux per (compared sun, sensor) from per-sun coefficients (exact references).
std::vector<double> lux_of(const RadianceMatrix& c, const std::vector<sky::SunRecord>& suns) {
  std::vector<double> e(suns.size() * c.rows());
  for (std::size_t i = 0; i < suns.size(); ++i)
    for (std::size_t s = 0; s < c.rows(); ++s)
      e[i * c.rows() + s] =
          rgb_to_photometric({c.at(s, i, 0), c.at(s, i, 1), c.at(s, i, 2)}) * suns[i].disc_radiance;
  return e;
}

struct Comparison {
  double sum_rms = 0, sum_worst = 0;       ///< relative, of the per-sensor sums
  double hourly_rms = 0;                   ///< RMS over sensors of hourly RMS / mean
  double indirect_sum_rms = 0;             ///< the same on the indirect sun alone
  double da_worst = 0, da_mean_abs = 0;    ///< DA300 points
  double udi_worst = 0;                    ///< UDI 100-2000 points
  double mean_da_a = 0, mean_da_b = 0;
};

/// Compare total = base + indirect_a against base + indirect_b (b the reference), both
/// per (compared sun, sensor); `occupied` per compared sun.
Comparison compare(const std::vector<double>& base, const std::vector<double>& a, const std::vector<double>& b,
                   std::size_t sensors, const std::vector<char>& occupied, std::size_t occupied_hours) {
  Comparison r;
  const std::size_t n = base.size() / sensors;
  for (std::size_t s = 0; s < sensors; ++s) {
    double sa = 0, sb = 0, ia = 0, ib = 0, d2 = 0;
    int da_a = 0, da_b = 0, udi_a = 0, udi_b = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t k = i * sensors + s;
      const double ea = base[k] + a[k], eb = base[k] + b[k];
      sa += ea, sb += eb, ia += a[k], ib += b[k];
      d2 += (ea - eb) * (ea - eb);
      if (occupied[i]) {
        da_a += ea >= 300, da_b += eb >= 300;
        udi_a += ea >= 100 && ea <= 2000, udi_b += eb >= 100 && eb <= 2000;
      }
    }
    const double rel = sa / sb - 1;
    r.sum_rms += rel * rel;
    r.sum_worst = std::max(r.sum_worst, std::fabs(rel));
    const double hourly = std::sqrt(d2 / n) / (sb / n);
    r.hourly_rms += hourly * hourly;
    const double irel = ia / ib - 1;
    r.indirect_sum_rms += irel * irel;
    const double dda = 100.0 * (da_a - da_b) / double(occupied_hours);
    r.da_worst = std::max(r.da_worst, std::fabs(dda));
    r.da_mean_abs += std::fabs(dda) / sensors;
    r.udi_worst = std::max(r.udi_worst, std::fabs(100.0 * (udi_a - udi_b) / double(occupied_hours)));
    r.mean_da_a += 100.0 * da_a / double(occupied_hours) / sensors;
    r.mean_da_b += 100.0 * da_b / double(occupied_hours) / sensors;
  }
  r.sum_rms = std::sqrt(r.sum_rms / sensors);
  r.hourly_rms = std::sqrt(r.hourly_rms / sensors);
  r.indirect_sum_rms = std::sqrt(r.indirect_sum_rms / sensors);
  return r;
}

void print(const char* name, const Comparison& c) {
  std::printf("  %-34s sums RMS %.2f %% (largest %.2f %%), hourly RMS %.2f %%, indirect-sun sums RMS %.2f %%;"
              " DA300 largest %.2f points (mean |d| %.3f; %.2f vs %.2f %%), UDI100-2000 largest %.2f points\n",
              name, 100 * c.sum_rms, 100 * c.sum_worst, 100 * c.hourly_rms, 100 * c.indirect_sum_rms, c.da_worst,
              c.da_mean_abs, c.mean_da_a, c.mean_da_b, c.udi_worst);
}

/// RADIANCE's sun-only hour (refdata e_sun: 21 March 12:00, a 0.533 deg sun of radiance
/// 6.788e6 W/(sr m2) toward (0.070984, -0.615818, 0.784685), no sky, no ground): rtrace -ab 7
/// per sensor against (a) exact direct + sun-bin indirect, (b) exact direct + exact indirect
/// with 10 times the photons, (c) the sun spread into the 4 nearest Tregenza patches times
/// the sky coefficients (gendaymtx's weights 1/(1.002 - cos)), i.e. the spread-sun mode.
void radiance_sun_hour(const engine::Scene& scene, const std::vector<engine::Material>& materials,
                       const engine::ReceiverPlane& plane, const std::vector<SensorPoint>& sensors,
                       const RadianceMatrix& sky_c, const sky::PatchBasis& basis, int sun_mf,
                       const engine::TracingOptions& tracing, const engine::CoefficientOptions& estimating) {
  const std::string path = std::string(DAYPHOTON_BENCH_SOURCE_DIR) +
                           "/../shared/refdata/results/e_sun/sun_test_illuminance.csv";
  std::FILE* f = std::fopen(path.c_str(), "r");
  if (!f) {
    std::printf("RADIANCE sun hour: %s not found, skipped\n", path.c_str());
    return;
  }
  std::vector<double> ref, ys;
  char line[512];
  std::fgets(line, sizeof line, f);  // header
  while (std::fgets(line, sizeof line, f)) {
    int index;
    double x, y, classic;
    if (std::sscanf(line, "%d,%lf,%lf,%lf", &index, &x, &y, &classic) == 4) {
      ref.push_back(classic);
      ys.push_back(y);
      if (std::fabs(sensors[ref.size() - 1].position.x - x) > 1e-6 || std::fabs(sensors[ref.size() - 1].position.y - y) > 1e-6)
        std::printf("RADIANCE sun hour: sensor %d is at (%g, %g), ours elsewhere\n", index, x, y);
    }
  }
  std::fclose(f);
  if (ref.size() != sensors.size()) return;
  const Vec3 d = normalize(Vec3{0.070984, -0.615818, 0.784685});
  const double radiance = 6.788e6;
  sky::SunRecord sun;
  sun.direction = d;
  sun.disc_radiance = radiance;
  const RadianceMatrix direct = study::direct_sun_coefficients(scene, materials, sensors, {sun});
  // (a) the sun bins of this sun's stencil, traced as the pipeline traces them.
  const engine::SunBins bins = engine::SunBins::for_suns({d}, sun_mf);
  const engine::TracedPhotons bp = study::trace_sun_bins(scene, materials, bins, {plane}, tracing);
  const RadianceMatrix bc =
      study::sun_bin_coefficients(scene, materials, bins.sources(sky::SunHalfAngle_rad),
                                  engine::GridPhotons::for_plane(plane, bp.planes[0], bins.size()), sensors, estimating);
  const engine::SunStencil st = bins.weights(d);
  // (b) exact, 10 x photons.
  engine::SourceSet one;
  one.add_sun_disc(d, sky::SunHalfAngle_rad);
  engine::TracingOptions many = tracing;
  many.photons_per_source *= 10;
  many.seed = 77;
  const engine::TracedPhotons ep = engine::trace_photons(scene, materials, one, {plane}, many);
  const RadianceMatrix ec =
      study::sun_bin_coefficients(scene, materials, one, engine::GridPhotons::for_plane(plane, ep.planes[0], 1), sensors, estimating);
  // (c) spread: 4 nearest patch centres, weights 1/(1.002 - cos), E_n conserved.
  int best[4] = {-1, -1, -1, -1};
  double best_cos[4] = {-2, -2, -2, -2};
  for (int p = 1; p < basis.bin_count(); ++p) {
    const double c = dot(basis.centre(p), d);
    for (int k = 0; k < 4; ++k)
      if (c > best_cos[k]) {
        for (int j = 3; j > k; --j) best[j] = best[j - 1], best_cos[j] = best_cos[j - 1];
        best[k] = p, best_cos[k] = c;
        break;
      }
  }
  double wsum = 0;
  for (double c : best_cos) wsum += 1 / (1.002 - c);
  const double omega_sun = 2 * Pi * (1 - std::cos(sky::SunHalfAngle_rad));

  auto lux = [](const RadianceMatrix& m, std::size_t s, std::size_t j) {
    return rgb_to_photometric({m.at(s, j, 0), m.at(s, j, 1), m.at(s, j, 2)});
  };
  struct Stat {
    double sum2 = 0, bias = 0, ours = 0, theirs = 0;
    int n = 0;
    void add(double a, double b) {
      sum2 += (a / b - 1) * (a / b - 1), bias += a / b - 1, ours += a, theirs += b, ++n;
    }
  };
  Stat bins_out, exact_out, spread_out, bins_in, exact_in, spread_in, bins_back, exact_back, spread_back;
  for (std::size_t s = 0; s < sensors.size(); ++s) {
    double indirect = 0;
    for (int k = 0; k < st.count; ++k) indirect += st.weight[std::size_t(k)] * lux(bc, s, std::size_t(st.index[std::size_t(k)]));
    const double e_direct = lux(direct, s, 0) * radiance;
    const double e_bins = e_direct + indirect * radiance;
    const double e_exact = e_direct + lux(ec, s, 0) * radiance;
    double e_spread = 0;
    for (int k = 0; k < 4; ++k)
      e_spread += lux(sky_c, s, std::size_t(best[k])) * (1 / (1.002 - best_cos[k]) / wsum) * radiance * omega_sun /
                  basis.solid_angle_sr(best[k]);
    const bool outside = ys[s] >= 1.5;
    if (ys[s] >= 6.0) bins_back.add(e_bins, ref[s]), exact_back.add(e_exact, ref[s]), spread_back.add(e_spread, ref[s]);
    (outside ? bins_out : bins_in).add(e_bins, ref[s]);
    (outside ? exact_out : exact_in).add(e_exact, ref[s]);
    (outside ? spread_out : spread_in).add(e_spread, ref[s]);
  }
  std::printf("RADIANCE sun-only hour (refdata e_sun, rtrace -ab 7), per-sensor relative difference:\n");
  auto row = [](const char* name, const Stat& out, const Stat& in) {
    std::printf("  %-44s y >= 1.5 m (%d): mean %.0f vs %.0f lux, bias %+.2f %%, RMS %.2f %%;"
                "  y < 1.5 m (%d): mean %.0f vs %.0f lux, RMS %.2f %%\n",
                name, out.n, out.ours / out.n, out.theirs / out.n, 100 * out.bias / out.n,
                100 * std::sqrt(out.sum2 / out.n), in.n, in.ours / in.n, in.theirs / in.n,
                100 * std::sqrt(in.sum2 / in.n));
  };
  row("exact direct + sun-bin indirect", bins_out, bins_in);
  row("exact direct + exact indirect (10 x photons)", exact_out, exact_in);
  row("spread into 4 patches x sky coefficients", spread_out, spread_in);
  std::printf("  back rows y >= 6 m (%d sensors), mean ratio to rtrace: sun bins %.3f, exact %.3f, spread %.3f\n",
              bins_back.n, bins_back.ours / bins_back.theirs, exact_back.ours / exact_back.theirs,
              spread_back.ours / spread_back.theirs);
}

/// Annual sun energy through the ports (lumens x hours): the exact suns (disc at the
/// record's direction, tau(theta) cos(theta) per port) against the spread-sun mode's sun
/// (the spread matrix minus the sky-only matrix, each patch's radiance times the patch
/// integral of tau cos by a 16 x 16 midpoint rule), split into the hours with a sun record
/// and the others (suns below the horizon that gendaymtx still spreads into patches).
void window_sun_energy(const SceneDescription& description, const std::vector<engine::Material>& materials,
                       const sky::PatchBasis& basis, const study::AnnualSky& spread, const study::SkyAndSuns& ss) {
  Vec3 room_centre;
  double n_vertices = 0;
  for (const Surface& s : description.surfaces)
    for (const Vec3& v : s.vertices) room_centre = room_centre + v, n_vertices += 1;
  room_centre = room_centre / n_vertices;
  struct Port {
    Vec3 outward;
    double area = 0;
    int material = 0;
  };
  std::vector<Port> ports;
  for (const Surface& s : description.surfaces) {
    if (!s.port) continue;
    Vec3 n, c;  // Newell's normal (2 x area), centroid of the vertices
    for (std::size_t i = 0; i < s.vertices.size(); ++i) {
      n = n + cross(s.vertices[i], s.vertices[(i + 1) % s.vertices.size()]);
      c = c + s.vertices[i] / double(s.vertices.size());
    }
    Port p;
    p.area = 0.5 * length(n);
    p.outward = normalize(n);
    if (dot(p.outward, c - room_centre) < 0) p.outward = p.outward * -1.0;
    p.material = s.material;
    ports.push_back(p);
  }
  auto tau_cos = [&](const Vec3& w) {  // w toward the sky; sum over ports of A tau cos
    double sum = 0;
    for (const Port& p : ports) {
      const double c = dot(w, p.outward);
      if (c > 0) sum += p.area * c * materials[std::size_t(p.material)].straight_transmittance(-w, p.outward).y;
    }
    return sum;
  };
  const double omega_sun = 2 * Pi * (1 - std::cos(sky::SunHalfAngle_rad));
  double exact = 0;
  std::vector<char> sunny(ss.sky.steps.size(), 0);
  for (const sky::SunRecord& sun : ss.suns) {
    exact += 179.0 * sun.disc_radiance * omega_sun * tau_cos(sun.direction);
    sunny[sun.step] = 1;
  }
  std::vector<double> patch_integral(std::size_t(basis.bin_count()), 0.0);
  constexpr int N = 16;
  for (int p = 1; p < basis.bin_count(); ++p) {
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j) patch_integral[std::size_t(p)] += tau_cos(basis.sample_direction(p, (i + 0.5) / N, (j + 0.5) / N));
    patch_integral[std::size_t(p)] *= basis.solid_angle_sr(p) / (N * N);
  }
  double with_record = 0, without = 0;
  for (std::size_t t = 0; t < ss.sky.steps.size(); ++t) {
    double e = 0;
    for (int p = 1; p < basis.bin_count(); ++p)
      e += 179.0 * (double(spread.matrix.at(std::size_t(p), t, 1)) - double(ss.sky.matrix.at(std::size_t(p), t, 1))) *
           patch_integral[std::size_t(p)];
    (sunny[t] ? with_record : without) += e;
  }
  std::printf("annual sun energy through the ports (Mlm h): exact suns %.2f; spread-sun mode %.2f (%+.2f %%), of "
              "which %.2f in hours with a sun record (%+.2f %%) and %.3f in hours whose sun is below the horizon\n",
              exact / 1e6, (with_record + without) / 1e6, 100 * ((with_record + without) / exact - 1), with_record / 1e6,
              100 * (with_record / exact - 1), without / 1e6);
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t stride = argc > 1 ? std::stoul(argv[1]) : 1;
  const double fraction = argc > 2 && std::stod(argv[2]) > 0 ? std::stod(argv[2]) : study::SunBinPhotonFraction;
  std::unique_ptr<tbb::global_control> limit;
  if (argc > 4 && std::stoul(argv[4]) > 0)
    limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                  std::stoul(argv[4]));
  const project::Project proj =
      project::load_project(std::string(DAYPHOTON_BENCH_SOURCE_DIR) + "/projects/office/project.yaml");
  const project::Simulation& sim = proj.simulation;
  const std::size_t sun_bandwidth =
      argc > 3 && std::stoul(argv[3]) > 0 ? std::stoul(argv[3]) : study::sun_bin_bandwidth(std::size_t(sim.bandwidth));
  const double ref_factor = argc > 5 && std::stod(argv[5]) > 0 ? std::stod(argv[5]) : 1.0;
  const int sun_mf = argc > 6 && std::stoi(argv[6]) > 0 ? std::stoi(argv[6]) : sim.sun_mf;

  const SceneDescription description = project::build_scene_description(proj);
  const engine::Scene scene = engine::Scene::build(description);
  std::vector<engine::Material> materials;
  for (const MaterialSpec& m : description.materials) materials.push_back(engine::Material::from_spec(m));
  const SensorGrid& grid = description.grids.at(0);
  const engine::ReceiverPlane plane = engine::ReceiverPlane::from_grid(grid);
  const std::vector<SensorPoint>& sensors = grid.points;
  const std::size_t S = sensors.size();

  // Sky-only matrix and suns (RADIANCE-compatible conventions).
  const weather::HourlyWeather epw = weather::read_hourly_weather(proj.weather.path);
  const sky::SolarSite site = study::resolve_sun_site(proj.site, epw).solar;  // as the run
  const sky::PatchBasis basis = sky::PatchBasis::tregenza();
  const study::SkyAndSuns ss =
      study::annual_sky_and_suns(epw, site, basis, study::sun_excluded_sky_options(sim.ground_reflectance));
  const std::vector<sky::SunRecord>& suns = ss.suns;

  // Sky coefficients as the pipeline makes them (ground bin x 16 photons).
  auto t0 = Clock::now();
  const engine::SourceSet sky_sources = engine::SourceSet::sky_bins(basis);
  engine::TracingOptions sky_tracing;
  sky_tracing.photons_per_source = std::size_t(sim.photons_per_bin);
  sky_tracing.seed = sim.seed;
  sky_tracing.keep_surface_photons = false;
  sky_tracing.source_photon_factor.assign(sky_sources.size(), 1.0);
  sky_tracing.source_photon_factor[0] = 16.0;
  engine::CoefficientOptions estimating;
  estimating.density.bandwidth = std::size_t(sim.bandwidth);
  estimating.direct.samples_per_source = sim.direct_samples_per_bin;
  estimating.direct.seed = sim.seed;
  RadianceMatrix sky_c, sky_c_direct;
  {
    const engine::TracedPhotons traced = engine::trace_photons(scene, materials, sky_sources, {plane}, sky_tracing);
    const engine::GridPhotons gp = engine::GridPhotons::for_plane(plane, traced.planes[0], sky_sources.size());
    engine::DaylightCoefficients dc = engine::daylight_coefficients(scene, materials, sky_sources, gp, sensors, estimating);
    sky_c = dc.to_matrix();
    dc.caustic.assign(dc.caustic.size(), Vec3{});
    dc.global.assign(dc.global.size(), Vec3{});
    sky_c_direct = dc.to_matrix();  // the direct part alone
  }
  const double t_sky = seconds_since(t0);
  const metrics::IlluminanceTable sky_table = study::annual_illuminance(sky_c, ss.sky.matrix, ss.sky.steps);

  // Sun bins: chosen, traced, estimated.
  std::vector<Vec3> directions;
  for (const sky::SunRecord& s : suns) directions.push_back(s.direction);
  const engine::SunBins bins = engine::SunBins::for_suns(directions, sun_mf);
  engine::TracingOptions sun_tracing;
  sun_tracing.photons_per_source =
      static_cast<std::size_t>(std::llround(double(sim.photons_per_bin) * fraction));
  sun_tracing.seed = sim.seed;
  sun_tracing.keep_surface_photons = false;
  engine::CoefficientOptions sun_estimating = estimating;
  sun_estimating.density.bandwidth = sun_bandwidth;
  t0 = Clock::now();
  const engine::TracedPhotons bin_photons = study::trace_sun_bins(scene, materials, bins, {plane}, sun_tracing);
  const double t_bins_trace = seconds_since(t0);
  std::size_t traced_bins = 0, stored = bin_photons.planes[0].size();
  for (const engine::SourceTally& t : bin_photons.tallies) traced_bins += t.stored_global + t.stored_caustic > 0;
  t0 = Clock::now();
  const RadianceMatrix bin_c = study::sun_bin_coefficients(
      scene, materials, bins.sources(sky::SunHalfAngle_rad),
      engine::GridPhotons::for_plane(plane, bin_photons.planes[0], bins.size()), sensors, sun_estimating);
  const double t_bins_estimate = seconds_since(t0);

  // Exact direct sun, every hour.
  t0 = Clock::now();
  const RadianceMatrix direct = study::direct_sun_coefficients(scene, materials, sensors, suns,
                                                              study::SunDirectSamples, sim.seed);
  const double t_direct = seconds_since(t0);
  const metrics::IlluminanceTable direct_table = study::direct_sun_table(direct, suns, ss.sky.steps);
  const metrics::IlluminanceTable indirect_table = study::indirect_sun_table(bin_c, bins, suns, ss.sky.steps);

  // Compared hours and the exact references.
  double minimum_bound = 0;
  {
    const engine::SourceSet bin_sources = bins.sources(sky::SunHalfAngle_rad);
    const engine::PortEmitter emitter(scene, bin_sources);
    for (std::size_t i = 0; i < bins.size(); ++i) minimum_bound = std::max(minimum_bound, emitter.bound_flux(i));
    minimum_bound *= study::SunBinMinimumBoundFraction;
  }
  std::vector<sky::SunRecord> compared;
  for (std::size_t i = 0; i < suns.size(); i += stride) compared.push_back(suns[i]);
  t0 = Clock::now();
  engine::TracingOptions ref_tracing = sun_tracing;
  ref_tracing.photons_per_source = static_cast<std::size_t>(double(ref_tracing.photons_per_source) * ref_factor);
  const RadianceMatrix ref_c = exact_sun_coefficients(scene, materials, plane, sensors, compared, ref_tracing,
                                                      sun_estimating, minimum_bound, 1000);
  const double t_ref = seconds_since(t0);
  const RadianceMatrix ref2_c = exact_sun_coefficients(scene, materials, plane, sensors, compared, ref_tracing,
                                                       sun_estimating, minimum_bound, 2000);
  const std::vector<double> ref = lux_of(ref_c, compared), ref2 = lux_of(ref2_c, compared);

  // Per (compared sun, sensor): sky + direct (shared), bins interpolated, nearest bin.
  const std::size_t n = compared.size();
  std::vector<double> base(n * S), interpolated(n * S), nearest(n * S);
  std::vector<char> occupied(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t t = compared[i].step;
    const double hour = ss.sky.steps[t].hour;
    occupied[i] = hour >= proj.metrics.occupancy_start_h && hour < proj.metrics.occupancy_end_h;
    const engine::SunStencil st = bins.weights(compared[i].direction);
    int best = 0;
    for (int k = 1; k < st.count; ++k)
      if (st.weight[std::size_t(k)] > st.weight[std::size_t(best)]) best = k;
    for (std::size_t s = 0; s < S; ++s) {
      base[i * S + s] = double(sky_table.lux(t, s)) + double(direct_table.lux(t, s));
      interpolated[i * S + s] = indirect_table.lux(t, s);
      const std::size_t j = std::size_t(st.index[std::size_t(best)]);
      nearest[i * S + s] =
          rgb_to_photometric({bin_c.at(s, j, 0), bin_c.at(s, j, 1), bin_c.at(s, j, 2)}) * compared[i].disc_radiance;
    }
  }
  std::size_t occupied_hours = 0;
  for (char o : occupied) occupied_hours += o;
  if (stride == 1) {  // the whole year: DA over all 3650 occupied hours, sunless ones as sky only
    occupied_hours = metrics::OccupancySchedule::daily_hours(ss.sky.steps, proj.metrics.occupancy_start_h,
                                                             proj.metrics.occupancy_end_h)
                         .occupied_count();
  }
  // Sunless occupied hours do not change any difference; with stride 1 they enter the
  // percentages as the same value on both sides (counted below for the absolute DA).
  std::vector<int> da_sunless(S, 0);
  if (stride == 1) {
    std::vector<char> sunny(ss.sky.steps.size(), 0);
    for (const sky::SunRecord& s : suns) sunny[s.step] = 1;
    for (std::size_t t = 0; t < ss.sky.steps.size(); ++t) {
      const double hour = ss.sky.steps[t].hour;
      if (sunny[t] || hour < proj.metrics.occupancy_start_h || hour >= proj.metrics.occupancy_end_h) continue;
      for (std::size_t s = 0; s < S; ++s) da_sunless[s] += sky_table.lux(t, s) >= 300;
    }
  }
  double sunless_da_mean = 0;
  for (int d : da_sunless) sunless_da_mean += 100.0 * d / double(occupied_hours) / S;

  std::printf("office, sun bins on Reinhart MF %d: %zu bins (%zu receive light) for %zu sun hours\n", sun_mf,
              bins.size(), traced_bins, suns.size());
  std::printf("  sun-bin photons %zu per bin (%.3f x %lld), sun bandwidth %zu; %zu plane photons stored\n",
              sun_tracing.photons_per_source, fraction, sim.photons_per_bin, sun_bandwidth, stored);
  std::printf("  times: sky coefficients %.2f s, sun bins traced %.2f s, estimated %.2f s, exact direct sun "
              "(%zu hours x %zu sensors x %d rays) %.2f s, exact reference (%zu suns) %.2f s\n",
              t_sky, t_bins_trace, t_bins_estimate, suns.size(), S, study::SunDirectSamples, t_direct, n, t_ref);
  std::printf("compared: %zu sun hours (every %zu-th), %zu occupied%s\n", n, stride, occupied_hours,
              stride == 1 ? " hours of the year (DA, UDI over the year)" : " (DA, UDI over these)");
  // Indirect sun summed over the compared hours, per sensor row: sun bins / exact.
  {
    std::vector<double> ys;
    for (const SensorPoint& p : sensors)
      if (std::find(ys.begin(), ys.end(), p.position.y) == ys.end()) ys.push_back(p.position.y);
    std::sort(ys.begin(), ys.end());
    std::printf("indirect sun over the compared hours per row, sun bins / exact:");
    for (double y : ys) {
      double a = 0, b = 0;
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t s = 0; s < S; ++s)
          if (sensors[s].position.y == y) a += interpolated[i * S + s], b += ref[i * S + s];
      std::printf(" %.3f", a / b);
    }
    std::printf("\n");
  }
  print("sun bins vs exact", compare(base, interpolated, ref, S, occupied, occupied_hours));
  print("nearest bin vs exact", compare(base, nearest, ref, S, occupied, occupied_hours));
  print("exact (seeds 2) vs exact: noise", compare(base, ref2, ref, S, occupied, occupied_hours));
  if (stride == 1)
    std::printf("  (add %.2f points of sunless occupied hours to the mean DA300 values above)\n", sunless_da_mean);
  radiance_sun_hour(scene, materials, plane, sensors, sky_c, basis, sun_mf, sun_tracing, sun_estimating);
  const study::AnnualSky spread =
      study::annual_sky_from_weather(epw, site, basis, study::radiance_compatible_sky_options(sim.ground_reflectance));
  window_sun_energy(description, materials, basis, spread, ss);
  // The sun's part of the annual illuminance per sensor row, direct and indirect, in both
  // modes: spread = sky coefficients (direct part / photon part) x (spread - sky-only
  // matrix); bins = exact direct + interpolated indirect. Mean over the occupied hours.
  {
    RadianceMatrix sun_only = spread.matrix;
    for (std::size_t i = 0; i < sun_only.data().size(); ++i) sun_only.data()[i] -= ss.sky.matrix.data()[i];
    const metrics::IlluminanceTable spread_all = study::annual_illuminance(sky_c, sun_only, ss.sky.steps);
    const metrics::IlluminanceTable spread_direct = study::annual_illuminance(sky_c_direct, sun_only, ss.sky.steps);
    const metrics::OccupancySchedule occ = metrics::OccupancySchedule::daily_hours(
        ss.sky.steps, proj.metrics.occupancy_start_h, proj.metrics.occupancy_end_h);
    std::vector<double> ys;
    for (const SensorPoint& p : sensors)
      if (std::find(ys.begin(), ys.end(), p.position.y) == ys.end()) ys.push_back(p.position.y);
    std::sort(ys.begin(), ys.end());
    std::printf("sun part of the mean occupied illuminance per row (lux): direct spread / exact; indirect spread / sun bins\n");
    for (double y : ys) {
      double sd = 0, ed = 0, si = 0, bi = 0;
      int count = 0;
      for (std::size_t s = 0; s < S; ++s) {
        if (sensors[s].position.y != y) continue;
        ++count;
        for (std::size_t t = 0; t < ss.sky.steps.size(); ++t) {
          if (!occ.occupied(t)) continue;
          sd += spread_direct.lux(t, s), ed += direct_table.lux(t, s);
          si += double(spread_all.lux(t, s)) - spread_direct.lux(t, s), bi += indirect_table.lux(t, s);
        }
      }
      const double k = 1.0 / (count * double(occ.occupied_count()));
      std::printf("  y %.1f m: direct %.0f / %.0f, indirect %.1f / %.1f\n", y, sd * k, ed * k, si * k, bi * k);
    }
  }
  return 0;
}
