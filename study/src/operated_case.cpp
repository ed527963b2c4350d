// The operated result: see operated_case.h.
#include "operated_case.h"

#include <filesystem>

#include "dayphoton/core/atomic_file.h"
#include "dayphoton/core/diagnostics.h"
#include "dayphoton/study/annual_study.h"
#include "dayphoton/study/operated_shading.h"
#include "dayphoton/study/project_metric_settings.h"
#include "dayphoton/study/result_files.h"
#include "dayphoton/study/results_model_builder.h"
#include "json_text.h"
#include "json_values.h"

namespace dayphoton::study {

/// The operated result (operated_shading.h) of every grid into `dir`/<grid>/: the files of an
/// annual case (sensors, illuminance, metrics) plus shading_schedule.csv and operation.json.
/// Returns summary.json's `operated` object.
nlohmann::json run_operated(const project::Project& project, const project::OperationSpec& op,
                            const CaseTables& open, const CaseTables& shaded, const std::string& dir,
                            RunContext& ctx) {
  const SkyAndSuns& ss = *ctx.sky_and_suns;  // both cases' annual step built it
  const AnnualOutputs which = annual_outputs_of(project);
  ShadingRule rule;
  rule.direct_sun_threshold_lux = op.direct_sun_threshold_lux;
  rule.sunlit_limit_percent = op.sunlit_limit_percent;
  const std::string open_name = op.open.value, shaded_name = op.shaded.value;
  nlohmann::json grids = nlohmann::json::array();
  for (std::size_t g = 0; g < open.grids.size(); ++g) {
    const CaseTables::Grid& o = open.grids[g];
    const CaseTables::Grid& c = shaded.grids.at(g);  // the same grids: variants share the sensors
    AnnualStudySettings settings = annual_settings_of(project, ctx.weather, ctx.openings_of(o.name), o.name);
    settings.sensor_area_m2 = o.area_m2;
    const std::string folder = join_path(dir, o.name);
    ctx.progress.start("operated " + o.name, o.illuminance.step_count(), "hours");
    const OperatedStudy operated = compute_operated_study(
        o.illuminance, c.illuminance, o.direct_sun, rule, settings, ss.sky.daylight_hours_quantity,
        ss.sky.daylight_hours_source,
        "operated shading: per hour '" + shaded_name + "' when more than " + format_number(rule.sunlit_limit_percent) +
            " % of the sensors see direct sun in '" + open_name + "', else '" + open_name + "'; " + ss.sky.description);
    std::filesystem::create_directories(folder);
    write_sensors_csv(o.sensors, o.area_m2, join_path(folder, "sensors.csv"));
    ctx.outputs.record(join_path(folder, "sensors.csv"));
    ctx.outputs.record(write_annual_outputs(operated.study, o.sensors, settings, folder, which));
    write_shading_schedule_csv(operated, join_path(folder, "shading_schedule.csv"));
    const nlohmann::json operation = operation_value(operated, rule, open_name, shaded_name);
    write_file_atomically(join_path(folder, "operation.json"), json_text(operation) + "\n");
    ctx.outputs.record({join_path(folder, "shading_schedule.csv"), join_path(folder, "operation.json")});
    ctx.progress.advance(o.illuminance.step_count());
    ctx.progress.end();
    ctx.log.line("operated " + o.name + ": '" + shaded_name + "' in " + std::to_string(operated.schedule.shaded_steps()) +
                 " of " + std::to_string(operated.schedule.shaded.size()) + " hours (" +
                 std::to_string(operated.shaded_occupied_hours) + " of " +
                 std::to_string(operated.study.occupied_hours) + " occupied), '" + open_name + "' otherwise");
    ctx.report.grids.push_back({"operated/" + o.name, o.sensors.size(), folder});
    add_operated_grid(*ctx.results, o.name, relative_folder(ctx.report.output_dir, folder), operated.study, settings, which);
    grids.push_back({{"name", o.name},
                     {"sensors", o.sensors.size()},
                     {"folder", folder},
                     {"annual", grid_metrics_value(operated.study, settings)},
                     {"operation", operation}});
  }
  return {{"open", open_name}, {"shaded", shaded_name}, {"folder", dir}, {"grids", grids}};
}

}  // namespace dayphoton::study
