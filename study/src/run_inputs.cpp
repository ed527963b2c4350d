// What a run reads and checks first: see run_inputs.h.
#include "dayphoton/study/run_inputs.h"

#include "dayphoton/core/diagnostics.h"
#include "dayphoton/study/point_in_time.h"

namespace dayphoton::study {

RunInputs read_run_inputs(const project::Project& project) {
  RunInputs inputs;
  // The weather file and the site of its sun first: a time zone that is not the file's is an
  // input error.
  if (project.study == project::StudyKind::Annual) {
    inputs.weather = weather::read_hourly_weather(project.weather.path);
    inputs.sun_site = resolve_sun_site(project.site, *inputs.weather);
    inputs.below_horizon = annual_below_horizon_direct(*inputs.weather, *inputs.sun_site);
  }
  // The points in time whose sun needs no tracing.
  check_points_in_time(project.points_in_time,
                       point_in_time_site(project, inputs.sun_site ? &*inputs.sun_site : nullptr));
  // Operated shading needs each hour's direct sun (the loader says so for project files).
  if (project.operation && project.simulation.sun != project::SunMode::Bins)
    throw InputError(project.operation->location, "operation needs the direct sun of every hour: set simulation.sun to 'bins'");
  return inputs;
}

}  // namespace dayphoton::study
