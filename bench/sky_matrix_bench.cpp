// Benchmark: time to build an annual sky matrix (8760 records of the example project's EPW)
// for Tregenza (MF 1) and Reinhart MF 4, in the gendaymtx-compatible mode and in dayphoton's
// patch-mean mode, on all cores. gendaymtx on the same machine kind (refdata c_annual README):
// MF 1 0.75 s ascii / 0.18 s float, MF 4 13.3 s ascii / 3.7 s float (including output).
// Each mode also with the quadrant deltas of the annual product's sub-patches
// (SkyMatrixOptions::quadrant_deltas), whose cost is the difference.
#include <chrono>
#include <cstdio>
#include <sstream>
#include <string>

#include "dayphoton/sky/sky_matrix.h"

using namespace dayphoton;
using Clock = std::chrono::steady_clock;

int main(int argc, char** argv) {
  const std::string epw_path = argc > 1 ? argv[1] : "projects/office/USA_CA_Oakland.Intl.AP.724930_TMY3.epw";
  const weather::HourlyWeather epw = weather::read_hourly_weather(epw_path);
  const sky::SolarSite site = sky::solar_site_of(epw);
  std::printf("sky matrix benchmark: %s, %zu records\n", epw_path.c_str(), epw.records.size());
  std::printf("%-6s %-22s %10s %12s %14s\n", "basis", "mode", "build_s", "float_out_s", "patch-hours/s");
  for (int mf : {1, 4}) {
    const sky::PatchBasis basis = mf == 1 ? sky::PatchBasis::tregenza() : sky::PatchBasis::reinhart(mf);
    for (int run = 0; run < 4; ++run) {
      const int compatible = run < 2, deltas = run % 2;
      sky::SkyMatrixOptions options =
          compatible ? sky::SkyMatrixOptions::gendaymtx_compatible() : sky::SkyMatrixOptions{};
      options.quadrant_deltas = deltas == 1;
      const auto t0 = Clock::now();
      const sky::SkyMatrix m = sky::build_sky_matrix(epw, site, basis, options);
      const auto t1 = Clock::now();
      std::ostringstream sink;
      m.matrix.write(sink, MatrixFormat::Float);
      const auto t2 = Clock::now();
      const double build = std::chrono::duration<double>(t1 - t0).count();
      const double out = std::chrono::duration<double>(t2 - t1).count();
      std::printf("MF %-3d %-22s %10.3f %12.3f %14.3g\n", mf,
                  compatible ? (deltas ? "compatible + deltas" : "gendaymtx-compatible")
                             : (deltas ? "patch mean + deltas" : "patch mean"),
                  build, out, double(basis.bin_count()) * double(epw.records.size()) / build);
    }
  }
  return 0;
}
