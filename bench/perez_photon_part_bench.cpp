// perez_photon_part_bench: how far the annual illuminance's PHOTON part (the photon
// coefficients x the hourly Perez sky vector, patch-centre values as the annual study builds
// it) is from the photon part under the continuous Perez sky of the same hour, on the grids of
// a project (projects/office: the work plane; projects/wall_sensors: work plane, back wall,
// west wall), for hours of four kinds (overcast: Perez clearness bin 1; intermediate: bins
// 2-5; clear with the sun high, >= 40 degrees, and low, 5-20 degrees; bins 6-8) of the
// project's weather file.
//
// The reference is exact up to Monte Carlo noise and shares that noise with the basis sum: the
// sky photons are traced once per hour with that hour's sky ratios (engine/sky_ratios.h:
// each sky-bin photon carries L(w) / L_ref,p, the hour's continuous sky in its emission
// direction over a reference luminance of its bin), so the estimate with each flux times its
// ratio, summed with L_ref,p, is the photon part under the continuous sky itself
// (engine::DaylightCoefficients::photon_on_sky; the gathered rows' specular paths take the
// exact ratio in their own direction). The ratios draw no random numbers, so every hour traces
// the very same photons and the basis coefficients are the same bit for bit; the two sums
// differ by the basis alone plus the noise of the ratio-weighting. L_ref,p is the bin's centre
// value, raised to 0.55 x its largest luminance where the sky varies more than 1.8-fold within
// the bin (the circumsolar bins of clear skies), so that every ratio fits the record's 12-bit
// code (at most 2): any L_ref,p gives the exact sum.
//
// Beside it, the study's sub-patch correction (study/sub_patch_shares.h) of the coefficients'
// shares with the sky matrix's quadrant deltas: the direct part's alone (the shares as the
// direct part has them) and, where the engine gives the photon part's shares
// (engine::DaylightCoefficients::photon_quadrants), the photon part's, whose error against the
// same reference is reported too.
//
// The hour's total (the denominator of "% of total") is the study's annual table of a normal
// run of the project (sun included); sigma is the reported standard error of the hour's sky
// part (sqrt(sum_p lum(L_p)^2 (var_direct + var_photon)) x 179 lux), and sigma_ph the photon
// part's alone.
//
// Usage: perez_photon_part_bench [office|wall_sensors|PROJECT.yaml] [hours_per_kind=3] [seed]
// Writes a run under $TMPDIR/dayphoton_perez_photon_part_bench (or /tmp).
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "dayphoton/core/units.h"
#include "dayphoton/engine/daylight_coefficients.h"
#include "dayphoton/engine/distant_source.h"
#include "dayphoton/engine/estimate_variance.h"
#include "dayphoton/engine/photon_tracer.h"
#include "dayphoton/engine/scene.h"
#include "dayphoton/project/project.h"
#include "dayphoton/sky/patch_basis.h"
#include "dayphoton/sky/perez.h"
#include "dayphoton/sky/sky_matrix.h"
#include "dayphoton/study/annual_sun.h"
#include "dayphoton/study/progress.h"
#include "dayphoton/study/results_model.h"
#include "dayphoton/study/simulation_plan.h"
#include "dayphoton/study/study_runner.h"
#include "dayphoton/study/sub_patch_shares.h"
#include "dayphoton/study/sun_site.h"
#include "dayphoton/weather/epw_reader.h"
#include "dayphoton/weather/site_clock.h"
#include "df_only_run.h"
#include "error_stats.h"
#include "perez_hour.h"
#include "sky_ratio_reference.h"

using namespace dayphoton;
namespace fs = std::filesystem;

namespace {

struct Climate {
  project::Project proj;
  weather::HourlyWeather epw;
  sky::SolarSite site;
  std::vector<weather::TimeStep> steps;
  sky::SkyMatrix centre;                 ///< as the annual study builds it, with its quadrant deltas
  std::vector<std::optional<Vec3>> sun;  ///< per record: the sun above the horizon
};

Climate make_climate(project::Project proj) {
  Climate c;
  c.proj = std::move(proj);
  c.epw = weather::read_hourly_weather(c.proj.weather.path);
  c.site = study::resolve_sun_site(c.proj.site, c.epw).solar;
  c.steps = weather::SiteClock::for_weather(c.epw).steps(c.epw.records);
  sky::SkyMatrixOptions options = study::sun_excluded_sky_options(c.proj.simulation.ground_reflectance);
  options.quadrant_deltas = true;
  c.centre = sky::build_sky_matrix(c.epw, c.site, study::basis_of(c.proj.simulation), options);
  c.sun.assign(c.steps.size(), std::nullopt);
  for (const sky::SunRecord& s : sky::daytime_sun_positions(c.epw, c.site, options)) c.sun[s.step] = s.direction;
  return c;
}

sky::PerezInputs perez_inputs(const Climate& c, std::size_t t) { return bench::perez_inputs_of(c.epw, c.steps, c.sun, t); }

Vec3 column(const RadianceMatrix& m, std::size_t p, std::size_t t) { return {m.at(p, t, 0), m.at(p, t, 1), m.at(p, t, 2)}; }

/// The continuous Perez sky of record t as perez_sky_component_bench takes it (the model
/// times gendaymtx's sky colour, the matrix's ground below the horizon).
engine::ContinuousSky continuous_sky(const Climate& c, std::size_t t) {
  return bench::continuous_perez_sky(perez_inputs(c, t), column(c.centre.matrix, 0, t), "record " + std::to_string(t));
}

/// Hours with the sun between the altitudes and a clearness bin in [bin_lo, bin_hi], n of them
/// evenly spread over the year's candidates.
std::vector<std::size_t> pick_hours(const Climate& c, int bin_lo, int bin_hi, double alt_lo_deg, double alt_hi_deg,
                                    int n) {
  std::vector<std::size_t> candidates;
  for (std::size_t t = 0; t < c.steps.size(); ++t) {
    if (!c.sun[t]) continue;
    const double alt = std::asin(c.sun[t]->z) * 180.0 / Pi;
    if (alt < alt_lo_deg || alt > alt_hi_deg) continue;
    if (!(c.epw.records[t].diffuse_horizontal_w_m2.value_or(0.0) > 0)) continue;
    const int bin = sky::perez_state(perez_inputs(c, t)).bin;
    if (bin >= bin_lo && bin <= bin_hi) candidates.push_back(t);
  }
  std::vector<std::size_t> out;
  for (int i = 0; i < n && !candidates.empty(); ++i)
    out.push_back(candidates[(2 * std::size_t(i) + 1) * candidates.size() / (2 * std::size_t(n))]);
  return out;
}

/// A normal annual run of the project (no images, report, coefficients): its grids' tables.
std::map<std::string, metrics::IlluminanceTable> annual_run(const project::Project& proj, const fs::path& folder) {
  project::Project p = proj;
  p.study = project::StudyKind::Annual;
  p.outputs.annual_illuminance = p.outputs.metrics = true;
  p.outputs.images = p.outputs.report = p.outputs.coefficients = false;
  std::ostringstream log;
  study::Progress progress(log, study::ProgressStyle::Quiet);
  study::RunSettings settings;
  settings.output_dir = (folder / "results").string();
  settings.cache_dir = (folder / "cache").string();
  study::run_study(p, settings, progress);
  const study::ResultsModel model = study::read_results_model(settings.output_dir);
  std::map<std::string, metrics::IlluminanceTable> tables;
  for (const study::GridResult& g : model.cases.at(0).grids)
    if (g.annual) tables[g.name] = study::read_illuminance_table(settings.output_dir, g);
  return tables;
}

/// 179 sum_p sum_q Q_pq d_pq(t) for shares `q` ([s][p][3], the fourth the luminance `c_p` less
/// the three), lux.
double sub_patch_lux(const std::vector<float>& q, const std::vector<double>& coefficient_lum, std::size_t sources,
                     std::size_t s, const RadianceMatrix& deltas, std::size_t t) {
  double sum = 0;
  for (std::size_t p = 1; p < sources; ++p) {
    const float* x = q.data() + (s * sources + p) * engine::StoredQuadrants;
    const double q3 = coefficient_lum[s * sources + p] - x[0] - x[1] - x[2];
    for (std::size_t k = 0; k < 3; ++k) sum += double(x[k]) * deltas.at(4 * p + k, t, 0);
    sum += q3 * deltas.at(4 * p + 3, t, 0);
  }
  return RadianceWhiteEfficacy_lm_per_W * sum;
}

using Stats = bench::ErrorStats;

}  // namespace

int main(int argc, char** argv) {
  const std::string source = DAYPHOTON_BENCH_SOURCE_DIR;
  std::string which = argc > 1 ? argv[1] : "office";
  const int per_kind = argc > 2 ? std::max(1, std::atoi(argv[2])) : 3;
  const std::string project_path =
      which.size() > 5 && which.substr(which.size() - 5) == ".yaml" ? which : source + "/projects/" + which + "/project.yaml";
  project::Project proj = project::load_project(project_path);
  if (argc > 3) proj.simulation.seed = std::atoll(argv[3]);
  const char* tmp = std::getenv("TMPDIR");
  const fs::path folder = fs::path(tmp && *tmp ? tmp : "/tmp") / "dayphoton_perez_photon_part_bench";
  fs::remove_all(folder);
  fs::create_directories(folder);
  const auto w0 = std::chrono::steady_clock::now();
  const double c0 = bench::process_cpu_seconds();
  std::printf("perez_photon_part_bench %s, %d hours per kind, seed %lld, load average %s\n", project_path.c_str(),
              per_kind, static_cast<long long>(proj.simulation.seed), bench::load_average().c_str());

  const Climate climate = make_climate(proj);
  const std::map<std::string, metrics::IlluminanceTable> totals = annual_run(proj, folder);

  // The scene and the study's own options (simulation_plan.h), its grids but the .pts copies.
  const SceneDescription description = project::build_scene_description(proj);
  const engine::Scene scene = engine::Scene::build(description);
  std::vector<engine::Material> materials;
  for (const MaterialSpec& m : description.materials) materials.push_back(engine::Material::from_spec(m));
  std::vector<SensorGrid> grids;
  for (const SensorGrid& g : description.grids)
    if (g.name != "workplane_points") grids.push_back(g);
  const study::SimulationPlan plan = study::SimulationPlan::of(proj);
  const study::CaseLayout layout = study::CaseLayout::of(grids, scene, materials);
  const engine::SourceSet sources = engine::SourceSet::sky_bins(plan.basis);
  const std::size_t n_src = sources.size();

  const char* kind_names[4] = {"overcast", "intermediate", "clear, sun high", "clear, sun low"};
  const int kind_bins[4][2] = {{1, 1}, {2, 5}, {6, 8}, {6, 8}};
  const double kind_alt[4][2] = {{2, 90}, {2, 90}, {40, 90}, {5, 20}};
  std::vector<std::size_t> hours;
  std::vector<int> kind_of;
  for (int k = 0; k < 4; ++k)
    for (std::size_t t : pick_hours(climate, kind_bins[k][0], kind_bins[k][1], kind_alt[k][0], kind_alt[k][1], per_kind)) {
      hours.push_back(t);
      kind_of.push_back(k);
    }
  std::vector<engine::ContinuousSky> skies;
  for (std::size_t t : hours) skies.push_back(continuous_sky(climate, t));

  // [grid][kind]: per sensor-hour, the photon part's basis error in % of the hour's total,
  // of the photon part, and in units of sigma; the sub-patch estimate's likewise.
  struct KindStats {
    Stats of_total, of_photon, in_sigma, fixed_of_total, fixed_in_sigma, sigma_of_total, sigma_ph_of_photon;
  };
  std::map<std::string, std::array<KindStats, 4>> by_grid;
  std::vector<engine::DaylightCoefficients> first(grids.size());
  bool have_photon_quadrants = false;
  for (std::size_t i = 0; i < hours.size(); ++i) {
    const std::size_t t = hours[i];
    const std::vector<Vec3> reference = bench::reference_radiances(skies[i], plan.basis, *climate.sun[t]);
    std::vector<double> reference_lum;
    for (const Vec3& l : reference) reference_lum.push_back(engine::luminance_of(l));
    auto ratios = std::make_shared<const engine::SkyRatios>(skies[i], reference_lum);
    engine::TracingOptions tracing = plan.tracing_for(plan.sky_tracing, layout);
    tracing.sky_ratios = ratios;
    const double trace_c0 = bench::process_cpu_seconds();
    engine::TracedPhotons traced = engine::trace_photons(scene, materials, sources, layout.planes, tracing);
    const double trace_cpu = bench::process_cpu_seconds() - trace_c0;
    const sky::PerezState state = sky::perez_state(perez_inputs(climate, t));
    std::printf("%-16s %2d/%02d %4.1f h, Perez bin %d, sun %4.1f deg, diffuse %3.0f W/m2 (tracing %.1f CPU s)\n",
                kind_names[kind_of[i]], climate.steps[t].month, climate.steps[t].day, climate.steps[t].hour_lst,
                state.bin, std::asin(climate.sun[t]->z) * 180.0 / Pi,
                climate.epw.records[t].diffuse_horizontal_w_m2.value_or(0.0), trace_cpu);
    for (std::size_t g = 0; g < grids.size(); ++g) {
      const SensorGrid& grid = grids[g];
      const int plane = layout.plane_of_grid[g];
      const engine::GridPhotons photons =
          plane >= 0 ? engine::GridPhotons::for_plane(layout.planes[std::size_t(plane)],
                                                      traced.planes[std::size_t(plane)], n_src)
                     : engine::GridPhotons::for_gather(traced.surface, n_src);
      engine::CoefficientOptions options = plan.sky_estimating;
      options.photon_sky_bin_radiance_rgb = reference;
      options.photon_sky_ratios = ratios;
      engine::DaylightCoefficients c;
      if (i == 0) {
        options.direct.skies.clear();
        c = engine::daylight_coefficients(scene, materials, sources, photons, grid.points, options);
        first[g] = c;
      } else {
        c.sensors = grid.points.size();
        c.sources = n_src;
        c.caustic.assign(c.sensors * n_src, Vec3{0, 0, 0});
        c.global.assign(c.sensors * n_src, Vec3{0, 0, 0});
        engine::photon_coefficients(scene, materials, sources, photons, grid.points, options, c);
        c.direct = first[g].direct;
        c.direct_variance = first[g].direct_variance;
        c.direct_quadrants = first[g].direct_quadrants;
      }
      const std::vector<float>& photon_quadrants = c.photon_quadrants;
      have_photon_quadrants = have_photon_quadrants || !photon_quadrants.empty();
      std::vector<double> photon_lum(c.sensors * n_src);
      for (std::size_t k = 0; k < photon_lum.size(); ++k) photon_lum[k] = engine::luminance_of(c.caustic[k] + c.global[k]);
      Stats grid_bias;
      for (std::size_t s = 0; s < c.sensors; ++s) {
        double basis = 0, variance = 0, photon_variance = 0;
        for (std::size_t p = 0; p < n_src; ++p) {
          const std::size_t k = s * n_src + p;
          const Vec3 l = column(climate.centre.matrix, p, t);
          const double lum = engine::luminance_of(l);
          basis += engine::luminance_of(mul(c.caustic[k] + c.global[k], l));
          variance += lum * lum * (c.direct_variance[k] + c.photon_variance[k]);
          photon_variance += lum * lum * c.photon_variance[k];
        }
        basis *= RadianceWhiteEfficacy_lm_per_W;
        const double exact = RadianceWhiteEfficacy_lm_per_W * engine::luminance_of(c.photon_on_sky.irradiance[s]);
        const double sigma = RadianceWhiteEfficacy_lm_per_W * std::sqrt(variance);
        const double sigma_ph = RadianceWhiteEfficacy_lm_per_W * std::sqrt(photon_variance);
        const double total = totals.at(grid.name).lux(t, s);
        if (!(total > 0) || !(exact > 0)) continue;
        KindStats& st = by_grid[grid.name][std::size_t(kind_of[i])];
        st.of_total.add(100.0 * (basis - exact) / total);
        st.of_photon.add(100.0 * (basis - exact) / exact);
        st.in_sigma.add((basis - exact) / sigma);
        st.sigma_of_total.add(100.0 * sigma / total);
        st.sigma_ph_of_photon.add(100.0 * sigma_ph / exact);
        grid_bias.add(100.0 * (basis - exact) / total);
        if (!photon_quadrants.empty()) {
          const double fixed =
              basis + sub_patch_lux(photon_quadrants, photon_lum, n_src, s, climate.centre.quadrant_deltas, t);
          st.fixed_of_total.add(100.0 * (fixed - exact) / total);
          st.fixed_in_sigma.add((fixed - exact) / sigma);
        }
      }
      std::printf("    %-10s photon part's basis error, %% of total: mean %+6.3f, RMS %6.3f, worst %+6.3f\n",
                  grid.name.c_str(), grid_bias.mean(), grid_bias.rms(), grid_bias.worst);
    }
    std::fflush(stdout);
  }
  std::printf("\nper grid and kind of hour: the photon part's basis error (basis - continuous), mean / RMS / worst over "
              "sensor-hours, in %% of the hour's total and of the photon part, in units of the sky part's stated "
              "sigma; sigma in %% of the total; the photon part's own sigma in %% of it%s\n",
              have_photon_quadrants ? "; then with the photon part's sub-patch correction" : "");
  for (const auto& [name, kinds] : by_grid)
    for (int k = 0; k < 4; ++k) {
      const KindStats& st = kinds[std::size_t(k)];
      if (st.of_total.n == 0) continue;
      std::printf("  %-10s %-16s total %+6.3f/%5.3f/%+6.3f  photon %+6.2f/%5.2f  sigma-units %+5.2f/%4.2f  "
                  "sigma %5.3f  sigma_ph %5.2f",
                  name.c_str(), kind_names[k], st.of_total.mean(), st.of_total.rms(), st.of_total.worst,
                  st.of_photon.mean(), st.of_photon.rms(), st.in_sigma.mean(), st.in_sigma.rms(),
                  st.sigma_of_total.mean(), st.sigma_ph_of_photon.mean());
      if (st.fixed_of_total.n)
        std::printf("  | fixed: total %+6.3f/%5.3f/%+6.3f sigma-units %+5.2f/%4.2f", st.fixed_of_total.mean(),
                    st.fixed_of_total.rms(), st.fixed_of_total.worst, st.fixed_in_sigma.mean(),
                    st.fixed_in_sigma.rms());
      std::printf("\n");
    }
  std::printf("%.0f s wall, %.0f s CPU, load average %s\n",
              std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count(),
              bench::process_cpu_seconds() - c0, bench::load_average().c_str());
  return 0;
}
