// The shared helpers of a run's phases: see run_context.h.
#include "run_context.h"

#include <filesystem>
#include <memory>

namespace dayphoton::study {

engine::GridPhotons grid_photons_for(std::size_t g, const CaseLayout& layout, const engine::TracedPhotons& photons,
                                     std::size_t sources, project::PointEstimate estimate) {
  const int plane = layout.plane_of_grid[g];
  if (plane >= 0) {
    engine::GridPhotons gp = engine::GridPhotons::for_plane(layout.planes[static_cast<std::size_t>(plane)],
                                                            photons.planes[static_cast<std::size_t>(plane)], sources);
    if (layout.grid_gathers_near_cuts(g))
      gp.set_near_cut_gather(std::make_shared<const engine::GridPhotons>(engine::GridPhotons::for_gather(photons.surface, sources)));
    return gp;
  }
  return estimate == project::PointEstimate::Gather ? engine::GridPhotons::for_gather(photons.surface, sources)
                                                    : engine::GridPhotons::for_surfaces(photons.surface, sources);
}

AnnualOutputs annual_outputs_of(const project::Project& project) {
  AnnualOutputs which;
  which.illuminance = project.outputs.annual_illuminance;
  which.illuminance_csv = project.outputs.illuminance_csv;
  which.metrics = project.outputs.metrics;
  return which;
}

std::string join_path(const std::string& dir, const std::string& name) {
  return (std::filesystem::path(dir) / name).string();
}

}  // namespace dayphoton::study
