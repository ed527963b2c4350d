// point_in_time_photon_part_bench: how far the PHOTON part of a project's point-in-time cases
// (study/point_in_time.h) is from the photon part under the case's continuous sky, before and
// after the CIE general and weather cases took their photon part on the sub-patches of their
// sky (docs/photon-map.md, "The point-in-time photon part"). Three cases at one time of the
// project's weather file, a clear hour with the sun 5-20 degrees high (the median such hour of
// Perez clearness bins 6-8, as perez_photon_part_bench picks them):
//   - weather: that record (the annual study's sky column and quadrant deltas);
//   - cie12:   a CIE clear sky (type 12) for the sun at the same date and time, 10 klx diffuse;
//   - overcast: the CIE overcast sky, 10 klx.
// The reference, as in perez_photon_part_bench: the sky photons traced again once per case with
// that sky's ratios to reference luminances (bench/sky_ratio_reference.h), so that the estimate
// with each flux times its ratio is the photon part under the continuous sky itself on the
// same photons; the basis coefficients are the same bit for bit, so "basis - reference" is the
// basis's error plus the little noise of the ratio weighting.
//
// Before: every case's photon part is the patch-uniform sum (the weather case's sub-patch
// correction was the direct part's alone; the overcast case took, and takes, the daylight
// factor's continuous-sky correction scaled to its sky, which is this reference up to noise).
// After: the weather and cie12 cases add the photon part's sub-patch correction
// (sub_patch_correction_lux of sub_patch_shares(SharesOf::PhotonPart)) with the weather hour's
// and the CIE sky's own quadrant deltas (point_in_time_cie_quadrant_deltas); for the overcast
// case the same correction is shown for comparison only.
//
// Errors in % of the case's total illuminance (point_in_time.csv of a normal run of the project
// with these cases, sun included), in % of the photon part, and in units of the photon part's
// stated standard error; mean / RMS / worst over the sensors.
//
// Usage: point_in_time_photon_part_bench [office|wall_sensors|PROJECT.yaml] [seed]
// Writes a run under $TMPDIR/dayphoton_point_in_time_photon_part_bench (or /tmp).
#include <algorithm>
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
#include "dayphoton/study/annual_study.h"
#include "dayphoton/study/annual_sun.h"
#include "dayphoton/study/point_in_time.h"
#include "dayphoton/study/progress.h"
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

using Stats = bench::ErrorStats;

/// point_in_time.csv of a grid: per case name, the sensors' lux.
std::map<std::string, std::vector<double>> read_point_in_time(const fs::path& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> header;
  std::stringstream h(line);
  for (std::string cell; std::getline(h, cell, ',');) header.push_back(cell);
  std::map<std::string, std::vector<double>> out;
  while (std::getline(in, line)) {
    std::stringstream s(line);
    std::size_t k = 0;
    for (std::string cell; std::getline(s, cell, ','); ++k)
      if (k >= 4) out[header.at(k).substr(0, header[k].size() - 4)].push_back(std::stod(cell));  // "<name>_lux"
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string source = DAYPHOTON_BENCH_SOURCE_DIR;
  const std::string which = argc > 1 ? argv[1] : "office";
  const std::string project_path =
      which.size() > 5 && which.substr(which.size() - 5) == ".yaml" ? which : source + "/projects/" + which + "/project.yaml";
  project::Project proj = project::load_project(project_path);
  if (argc > 2) proj.simulation.seed = std::atoll(argv[2]);
  const char* tmp = std::getenv("TMPDIR");
  const fs::path folder = fs::path(tmp && *tmp ? tmp : "/tmp") / "dayphoton_point_in_time_photon_part_bench";
  fs::remove_all(folder);
  fs::create_directories(folder);
  const auto w0 = std::chrono::steady_clock::now();
  const double c0 = bench::process_cpu_seconds();
  std::printf("point_in_time_photon_part_bench %s, seed %lld, load average %s\n", project_path.c_str(),
              static_cast<long long>(proj.simulation.seed), bench::load_average().c_str());

  // The weather file's sky as the annual study builds it (sun excluded, quadrant deltas).
  const weather::HourlyWeather epw = weather::read_hourly_weather(proj.weather.path);
  const sky::SolarSite site = study::resolve_sun_site(proj.site, epw).solar;
  const std::vector<weather::TimeStep> steps = weather::SiteClock::for_weather(epw).steps(epw.records);
  const sky::PatchBasis basis = study::basis_of(proj.simulation);
  sky::SkyMatrixOptions sky_options = study::sun_excluded_sky_options(proj.simulation.ground_reflectance);
  sky_options.quadrant_deltas = true;
  const sky::SkyMatrix annual_matrix = sky::build_sky_matrix(epw, site, basis, sky_options);
  std::vector<std::optional<Vec3>> sun(steps.size());
  for (const sky::SunRecord& s : sky::daytime_sun_positions(epw, site, sky_options)) sun[s.step] = s.direction;
  study::SkyAndSuns annual;
  annual.sky.matrix = annual_matrix.matrix;
  annual.sky.quadrant_deltas = annual_matrix.quadrant_deltas;
  annual.sky.steps = study::time_stamps(epw);
  annual.suns = annual_matrix.suns;

  // The median clear hour with the sun 5-20 degrees high.
  std::vector<std::size_t> candidates;
  for (std::size_t t = 0; t < steps.size(); ++t) {
    if (!sun[t] || !(epw.records[t].diffuse_horizontal_w_m2.value_or(0.0) > 0)) continue;
    const double alt = std::asin(sun[t]->z) * 180.0 / Pi;
    if (alt < 5 || alt > 20) continue;
    const int bin = sky::perez_state(bench::perez_inputs_of(epw, steps, sun, t)).bin;
    if (bin >= 6 && bin <= 8) candidates.push_back(t);
  }
  if (candidates.empty()) {
    std::printf("no clear hour with a low sun in %s\n", proj.weather.path.c_str());
    return 1;
  }
  const std::size_t hour = candidates[candidates.size() / 2];
  const metrics::TimeStamp& stamp = annual.sky.steps[hour];

  std::vector<project::PointInTimeSpec> cases(3);
  for (project::PointInTimeSpec& c : cases) {
    c.month = stamp.month;
    c.day = stamp.day;
    c.hour_lst = stamp.hour;  // mid-hour: inside the record's hour
    c.diffuse_horizontal_illuminance_lux = 10000;
  }
  cases[0].name = "weather";
  cases[0].sky = project::PointSky::Weather;
  cases[1].name = "cie12";
  cases[1].sky = project::PointSky::CieGeneral;
  cases[1].cie_type = 12;
  cases[1].direct_normal_illuminance_lux = 60000;
  cases[2].name = "overcast";
  cases[2].sky = project::PointSky::CieOvercast;
  const double rho_g = proj.simulation.ground_reflectance;
  const sky::SolarSite case_site = site;  // point_in_time_site: the annual study's sun site
  const study::SkyAndSuns skies = study::point_in_time_skies(cases, case_site, basis, rho_g, &annual);
  const RadianceMatrix cie_deltas = study::point_in_time_cie_quadrant_deltas(cases, case_site, basis, rho_g);
  std::vector<int> sky_of_case;
  const std::vector<engine::ContinuousSky> cie_skies =
      study::point_in_time_continuous_skies(cases, case_site, rho_g, sky_of_case);
  std::vector<engine::ContinuousSky> continuous;
  continuous.push_back(bench::continuous_perez_sky(bench::perez_inputs_of(epw, steps, sun, hour),
                                                   Vec3{skies.sky.matrix.at(0, 0, 0), skies.sky.matrix.at(0, 0, 1),
                                                        skies.sky.matrix.at(0, 0, 2)},
                                                   "record " + std::to_string(hour)));
  continuous.push_back(cie_skies.at(std::size_t(sky_of_case[1])));
  continuous.push_back(cie_skies.at(std::size_t(sky_of_case[2])));
  for (const std::string& line : study::describe_points_in_time(cases, skies)) std::printf("%s\n", line.c_str());
  std::printf("  (the weather hour: Perez bin %d, sun %.1f deg, diffuse %.0f W/m2)\n",
              sky::perez_state(bench::perez_inputs_of(epw, steps, sun, hour)).bin, std::asin(sun[hour]->z) * 180.0 / Pi,
              epw.records[hour].diffuse_horizontal_w_m2.value_or(0.0));

  // The cases' totals: a normal run of the project with them (the after state, sun included).
  std::map<std::string, std::map<std::string, std::vector<double>>> totals;  // grid -> case -> lux
  {
    project::Project p = proj;
    p.points_in_time = cases;
    p.outputs.images = p.outputs.report = p.outputs.coefficients = false;
    p.outputs.annual_illuminance = p.outputs.metrics = false;
    std::ostringstream log;
    study::Progress progress(log, study::ProgressStyle::Quiet);
    study::RunSettings settings;
    settings.output_dir = (folder / "results").string();
    settings.cache_dir = (folder / "cache").string();
    study::run_study(p, settings, progress);
    for (const auto& entry : fs::directory_iterator(settings.output_dir))
      if (fs::exists(entry.path() / "point_in_time.csv"))
        totals[entry.path().filename().string()] = read_point_in_time(entry.path() / "point_in_time.csv");
  }

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

  std::printf("\nthe photon part's error against its continuous sky, mean / RMS / worst over the sensors: in %% of the "
              "case's total, in %% of the photon part, in units of the photon part's stated sigma (the overcast case "
              "takes the daylight factor's continuous-sky correction: its photon part is the reference itself)\n");
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const std::optional<Vec3> case_sun =
        cases[k].sky == project::PointSky::CieOvercast ? std::nullopt : std::optional<Vec3>(*sun[hour]);
    const std::vector<Vec3> reference = bench::reference_radiances(continuous[k], plan.basis, case_sun);
    std::vector<double> reference_lum;
    for (const Vec3& l : reference) reference_lum.push_back(engine::luminance_of(l));
    auto ratios = std::make_shared<const engine::SkyRatios>(continuous[k], reference_lum);
    engine::TracingOptions tracing = plan.tracing_for(plan.sky_tracing, layout);
    tracing.sky_ratios = ratios;
    engine::TracedPhotons traced = engine::trace_photons(scene, materials, sources, layout.planes, tracing);
    const RadianceMatrix& deltas = cases[k].sky == project::PointSky::Weather ? skies.sky.quadrant_deltas : cie_deltas;
    RadianceMatrix overcast_deltas;
    if (cases[k].sky == project::PointSky::CieOvercast) {  // for comparison only (not used by the cases)
      RadianceMatrix column(skies.sky.matrix.rows(), 1, 3);
      for (std::size_t p = 0; p < column.rows(); ++p)
        for (int c = 0; c < 3; ++c) column.at(p, 0, c) = skies.sky.matrix.at(p, k, c);
      const auto model = sky::make_cie_overcast_sky(sky::SkyScale::horizontal_illuminance_lux(10000));
      const RadianceMatrix d = sky::sky_vector_quadrant_deltas(*model, basis, column);
      overcast_deltas = RadianceMatrix(d.rows(), cases.size(), 1);
      for (std::size_t r = 0; r < d.rows(); ++r) overcast_deltas.at(r, k, 0) = d.at(r, 0, 0);
    }
    const RadianceMatrix& used = cases[k].sky == project::PointSky::CieOvercast ? overcast_deltas : deltas;
    for (std::size_t g = 0; g < grids.size(); ++g) {
      const int plane = layout.plane_of_grid[g];
      const engine::GridPhotons photons =
          plane >= 0 ? engine::GridPhotons::for_plane(layout.planes[std::size_t(plane)],
                                                      traced.planes[std::size_t(plane)], n_src)
                     : engine::GridPhotons::for_gather(traced.surface, n_src);
      engine::CoefficientOptions options = plan.sky_estimating;
      options.photon_sky_bin_radiance_rgb = reference;
      options.photon_sky_ratios = ratios;
      options.direct.skies.clear();
      options.direct.samples_per_source = 1;  // the direct part plays no role here
      const engine::DaylightCoefficients c =
          engine::daylight_coefficients(scene, materials, sources, photons, grids[g].points, options);
      const std::vector<double> fix =
          study::sub_patch_correction_lux(study::sub_patch_shares(c, study::SharesOf::PhotonPart), used, k);
      const std::vector<double>& total = totals.at(grids[g].name).at(cases[k].name);
      Stats before_total, before_photon, before_sigma, after_total, after_photon, after_sigma;
      for (std::size_t s = 0; s < c.sensors; ++s) {
        double basis_lux = 0, variance = 0;
        for (std::size_t p = 0; p < n_src; ++p) {
          const std::size_t i = s * n_src + p;
          const Vec3 l{skies.sky.matrix.at(p, k, 0), skies.sky.matrix.at(p, k, 1), skies.sky.matrix.at(p, k, 2)};
          basis_lux += engine::luminance_of(mul(c.caustic[i] + c.global[i], l));
          variance += engine::luminance_of(l) * engine::luminance_of(l) * c.photon_variance[i];
        }
        basis_lux *= RadianceWhiteEfficacy_lm_per_W;
        const double sigma = RadianceWhiteEfficacy_lm_per_W * std::sqrt(variance);
        const double exact = RadianceWhiteEfficacy_lm_per_W * engine::luminance_of(c.photon_on_sky.irradiance[s]);
        if (!(exact > 0) || !(total.at(s) > 0)) continue;
        before_total.add(100 * (basis_lux - exact) / total[s]);
        before_photon.add(100 * (basis_lux - exact) / exact);
        before_sigma.add((basis_lux - exact) / sigma);
        const double after = basis_lux + fix[s];
        after_total.add(100 * (after - exact) / total[s]);
        after_photon.add(100 * (after - exact) / exact);
        after_sigma.add((after - exact) / sigma);
      }
      std::printf("  %-9s %-10s basis: total %+6.3f/%5.3f/%+6.3f photon %+6.2f/%5.2f/%+6.2f sigma %+5.2f/%4.2f"
                  "  | sub-patches%s: total %+6.3f/%5.3f/%+6.3f photon %+6.2f/%5.2f/%+6.2f sigma %+5.2f/%4.2f\n",
                  cases[k].name.c_str(), grids[g].name.c_str(), before_total.mean(), before_total.rms(),
                  before_total.worst, before_photon.mean(), before_photon.rms(), before_photon.worst,
                  before_sigma.mean(), before_sigma.rms(),
                  cases[k].sky == project::PointSky::CieOvercast ? " (not used)" : "", after_total.mean(),
                  after_total.rms(), after_total.worst, after_photon.mean(), after_photon.rms(), after_photon.worst,
                  after_sigma.mean(), after_sigma.rms());
    }
    std::fflush(stdout);
  }
  std::printf("%.0f s wall, %.0f s CPU, load average %s\n",
              std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count(),
              bench::process_cpu_seconds() - c0, bench::load_average().c_str());
  return 0;
}
