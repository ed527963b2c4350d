// Compliance verdicts (study/compliance_verdicts.h) at their thresholds, the conditions that
// make a criterion "not assessed" (another metric setting, no ASE, a vertical grid, no
// annual results), and the building tables of the results model builder (set_building,
// project_title) against hand-computed areas and ratios.
#include "dayphoton/study/compliance_verdicts.h"

#include <gtest/gtest.h>

#include "dayphoton/study/results_model_builder.h"

using namespace dayphoton;
using namespace dayphoton::study;

namespace {

GridResult horizontal_grid(double sda, std::optional<double> ase, double mean_df, double min_df, double uniformity) {
  GridResult g;
  g.name = "g";
  g.orientation = GridOrientation::Horizontal;
  AnnualSummary a;
  a.time_steps = 8760;
  a.occupancy.kind = "daily";  // 08:00-18:00 every day: LM-83's analysis period
  a.sda_percent = sda;
  a.ase_percent = ase;
  a.en17037 = {{"minimum", 300, 100, 60, 97, true}, {"medium", 500, 300, 40, 80, false}, {"high", 750, 500, 10, 50, false}};
  g.annual = a;
  DaylightFactorSummary d;
  d.mean_percent = mean_df;
  d.min_percent = min_df;
  d.uniformity = uniformity;
  g.daylight_factor = d;
  return g;
}

const Verdict& find(const std::vector<Verdict>& vs, const std::string& standard, const std::string& criterion) {
  for (const Verdict& v : vs)
    if (v.standard.rfind(standard, 0) == 0 && v.criterion.rfind(criterion, 0) == 0) return v;
  throw std::runtime_error("no verdict " + standard + " " + criterion);
}

}  // namespace

// LM-83-12's sDA and ASE are over its analysis period, 8 am to 6 pm local clock time every day
// of a year (section 2.1.2), and LEED takes them: a school week, an hourly schedule or a part
// of a year gives metrics of other hours, "not assessed" with the reason (they read "pass"
// before); every day 08:00-18:00 written as a weekly plan, or with daylight saving time, is
// LM-83's. EN 17037 uses its daylight hours, not the occupancy: still assessed.
TEST(ComplianceVerdicts, Lm83AndLeedOnlyOverTheAnalysisPeriod) {
  GridResult school = horizontal_grid(60, 5, 2, 1, 0.5);
  school.annual->occupancy.kind = "weekly";
  school.annual->occupancy.description = "Monday-Friday 08:00-15:00; Saturday, Sunday closed";
  for (int d = 0; d < 5; ++d) school.annual->occupancy.week[static_cast<std::size_t>(d)] = {{8.0, 15.0}};
  for (const char* standard : {"IES", "LEED"}) {
    const Verdict v = find(grid_verdicts(school), standard, "sDA");
    EXPECT_EQ(v.outcome, "not assessed") << standard;
    EXPECT_NE(v.reason.find("Monday-Friday 08:00-15:00"), std::string::npos) << v.reason;
    EXPECT_NE(v.reason.find("not LM-83's analysis period"), std::string::npos) << v.reason;
  }
  EXPECT_EQ(find(grid_verdicts(school), "IES", "ASE").outcome, "not assessed");
  EXPECT_EQ(find(grid_verdicts(school), "EN 17037", "level").outcome, "pass");

  GridResult every_day = school;
  for (auto& day : every_day.annual->occupancy.week) day = {{8.0, 18.0}};
  every_day.annual->occupancy.daylight_saving = "eu";
  EXPECT_EQ(find(grid_verdicts(every_day), "IES", "sDA").outcome, "pass");
  EXPECT_EQ(find(grid_verdicts(every_day), "LEED", "sDA").reason, "2 points");
  every_day.annual->occupancy.holidays = {{12, 25, 12, 26}};
  EXPECT_EQ(find(grid_verdicts(every_day), "IES", "sDA").outcome, "not assessed");

  GridResult hourly = horizontal_grid(60, 5, 2, 1, 0.5);
  hourly.annual->occupancy.kind = "hourly";
  EXPECT_EQ(find(grid_verdicts(hourly), "IES", "sDA").outcome, "not assessed");
  GridResult short_day = horizontal_grid(60, 5, 2, 1, 0.5);
  short_day.annual->occupancy.end_h = 17;
  EXPECT_EQ(find(grid_verdicts(short_day), "LEED", "sDA").outcome, "not assessed");

  GridResult part_year = horizontal_grid(60, 5, 2, 1, 0.5);
  part_year.annual->time_steps = 7344;
  const Verdict v = find(grid_verdicts(part_year), "IES", "ASE");
  EXPECT_EQ(v.outcome, "not assessed");
  EXPECT_NE(v.reason.find("7344 hourly records"), std::string::npos) << v.reason;
  GridResult leap_year = horizontal_grid(60, 5, 2, 1, 0.5);
  leap_year.annual->time_steps = 8784;
  EXPECT_EQ(find(grid_verdicts(leap_year), "IES", "sDA").outcome, "pass");
}

TEST(ComplianceVerdicts, Lm83AndLeedAtTheirThresholds) {
  EXPECT_EQ(find(grid_verdicts(horizontal_grid(55, 10, 2, 1, 0.5)), "IES", "sDA").outcome, "pass");
  EXPECT_EQ(find(grid_verdicts(horizontal_grid(54.99, 10, 2, 1, 0.5)), "IES", "sDA").outcome, "fail");
  EXPECT_EQ(find(grid_verdicts(horizontal_grid(75, 10, 2, 1, 0.5)), "IES", "sDA").reason, "preferred level reached");
  EXPECT_EQ(find(grid_verdicts(horizontal_grid(55, 10, 2, 1, 0.5)), "IES", "ASE").outcome, "pass");
  const Verdict ase = find(grid_verdicts(horizontal_grid(55, 10.01, 2, 1, 0.5)), "IES", "ASE");
  EXPECT_EQ(ase.outcome, "fail");
  EXPECT_NE(ase.reason.find("glare"), std::string::npos);
  EXPECT_EQ(leed_v41_points(39.99), 0);
  EXPECT_EQ(leed_v41_points(40), 1);
  EXPECT_EQ(leed_v41_points(54.99), 1);
  EXPECT_EQ(leed_v41_points(55), 2);
  EXPECT_EQ(leed_v41_points(75), 3);
  const Verdict leed = find(grid_verdicts(horizontal_grid(60, 5, 2, 1, 0.5)), "LEED", "sDA");
  EXPECT_EQ(leed.outcome, "pass");
  EXPECT_EQ(leed.reason, "2 points");
  EXPECT_EQ(*leed.value, 60);
  EXPECT_EQ(find(grid_verdicts(horizontal_grid(39, 5, 2, 1, 0.5)), "LEED", "sDA").outcome, "fail");
}

TEST(ComplianceVerdicts, En17037AndBreeam) {
  const std::vector<Verdict> v = grid_verdicts(horizontal_grid(60, 5, 2.0, 0.1, 0.4));
  const Verdict& en = find(v, "EN 17037", "level");
  EXPECT_EQ(en.outcome, "pass");
  EXPECT_EQ(*en.value, 1);
  EXPECT_EQ(en.reason, "minimum level reached");
  // BREEAM: average >= 2 % and (uniformity >= 0.4 or minimum >= 0.8 %).
  EXPECT_EQ(find(v, "BREEAM", "").outcome, "pass");
  EXPECT_EQ(find(grid_verdicts(horizontal_grid(60, 5, 2.0, 0.8, 0.39)), "BREEAM", "").outcome, "pass");
  EXPECT_EQ(find(grid_verdicts(horizontal_grid(60, 5, 2.0, 0.79, 0.39)), "BREEAM", "").outcome, "fail");
  EXPECT_EQ(find(grid_verdicts(horizontal_grid(60, 5, 1.99, 1.5, 0.9)), "BREEAM", "").outcome, "fail");
  GridResult none = horizontal_grid(60, 5, 2, 1, 1);
  for (En17037Level& l : none.annual->en17037) l.passes = false;
  const std::vector<Verdict> none_verdicts = grid_verdicts(none);
  const Verdict& no_level = find(none_verdicts, "EN 17037", "level");
  EXPECT_EQ(no_level.outcome, "fail");
  EXPECT_EQ(no_level.reason, "no level reached");
}

TEST(ComplianceVerdicts, WhatCannotBeAssessedSaysWhy) {
  // Another DA threshold or time fraction: no LM-83 or LEED sDA verdict.
  GridResult other = horizontal_grid(80, 5, 3, 1, 0.5);
  other.annual->da_threshold_lux = 250;
  EXPECT_EQ(find(grid_verdicts(other), "IES", "sDA").outcome, "not assessed");
  EXPECT_NE(find(grid_verdicts(other), "LEED", "sDA").reason.find("sDA250/50%"), std::string::npos);
  // No ASE (spread sun); no EN 17037 levels.
  GridResult spread = horizontal_grid(80, std::nullopt, 3, 1, 0.5);
  spread.annual->en17037.clear();
  EXPECT_EQ(find(grid_verdicts(spread), "IES", "ASE").outcome, "not assessed");
  EXPECT_EQ(find(grid_verdicts(spread), "EN 17037", "level").outcome, "not assessed");
  // A vertical grid: nothing assessed, every verdict names the orientation.
  GridResult wall = horizontal_grid(80, 5, 3, 1, 0.5);
  wall.orientation = GridOrientation::Vertical;
  for (const Verdict& v : grid_verdicts(wall)) {
    EXPECT_EQ(v.outcome, "not assessed") << v.standard;
    EXPECT_FALSE(v.value.has_value());
    EXPECT_NE(v.reason.find("vertical"), std::string::npos);
  }
  // A daylight-factor study: BREEAM only; the model says what was not assessed.
  GridResult df_only = horizontal_grid(0, 0, 2.5, 1, 0.5);
  df_only.annual.reset();
  EXPECT_EQ(find(grid_verdicts(df_only), "BREEAM", "").outcome, "pass");
  EXPECT_EQ(find(grid_verdicts(df_only), "IES", "sDA").outcome, "not assessed");
  ResultsModel m;
  CaseResult c;
  c.grids = {df_only};
  m.cases = {c};
  assess_compliance(m);
  EXPECT_EQ(m.cases[0].grids[0].verdicts.size(), grid_verdicts(df_only).size());
  bool daylight_factor_study = false, view_out = false;
  for (const std::string& s : m.not_assessed) {
    daylight_factor_study = daylight_factor_study || s.find("daylight-factor study") != std::string::npos;
    view_out = view_out || s.find("view out") != std::string::npos;
  }
  EXPECT_TRUE(daylight_factor_study);
  EXPECT_TRUE(view_out);
}

TEST(ResultsModelBuilder, BuildingTablesFromTheProjectAndTheScene) {
  project::Project p;
  project::RoomSpec room;
  room.name = "classroom";
  room.size_m = {4, 3, 3};
  project::WindowSpec w;
  w.name = "south";
  w.wall = project::Wall::South;
  w.width_m = 2;
  w.height_m = 1;
  w.sill_m = 0.9;
  w.material = "glazing";
  w.frame_factor = 0.8;
  room.windows = {w};
  w.name = "east";
  w.wall = project::Wall::East;
  room.windows.push_back(w);
  project::RoofLightSpec light;
  light.name = "top";
  light.width_m = 1;
  light.length_m = 0.5;
  light.material = "glazing";
  room.roof_lights = {light};
  p.geometry.rooms = {room};
  SceneDescription scene;
  MaterialSpec walls;
  walls.name = "walls";
  walls.reflectance = {0.5, 0.5, 0.5};
  MaterialSpec glazing;
  glazing.name = "glazing";
  glazing.type = MaterialType::Glass;
  glazing.transmittance = {0.6, 0.6, 0.6};
  MaterialSpec unused = walls;
  unused.name = "unused";
  scene.materials = {walls, glazing, unused};
  Surface wall;
  wall.material = 0;
  wall.vertices = {{0, 0, 0}, {4, 0, 0}, {4, 0, 3}, {0, 0, 3}};
  Surface pane;
  pane.material = 1;
  pane.port = true;
  pane.vertices = {{1, 0, 1}, {3, 0, 1}, {3, 0, 2}, {1, 0, 2}};
  scene.surfaces = {wall, pane};
  CaseResult c;
  set_building(c, p, scene);
  ASSERT_EQ(c.materials.size(), 2u);  // the unused material is left out
  EXPECT_EQ(c.materials[0].name, "walls");
  EXPECT_EQ(c.materials[0].type, "lambertian");
  EXPECT_NEAR(*c.materials[0].reflectance, 0.5, 1e-12);
  EXPECT_FALSE(c.materials[0].transmittance.has_value());
  EXPECT_NEAR(c.materials[0].area_m2, 12, 1e-12);
  EXPECT_FALSE(c.materials[1].reflectance.has_value());
  EXPECT_NEAR(*c.materials[1].transmittance, 0.6, 1e-6);  // normal-incidence transmittance of the glass
  EXPECT_NEAR(c.opening_area_m2, 2, 1e-12);
  ASSERT_EQ(c.rooms.size(), 1u);
  const RoomSummary& r = c.rooms[0];
  EXPECT_EQ(r.floor_area_m2, 12);
  EXPECT_EQ(r.window_area_m2, 4);
  EXPECT_EQ(r.glazed_wall_area_m2, 4 * 3 + 3 * 3);  // the south and east walls
  EXPECT_EQ(r.roof_light_area_m2, 0.5);
  EXPECT_NEAR(r.window_to_wall_ratio(), 4.0 / 21, 1e-12);
  EXPECT_NEAR(r.window_to_floor_ratio(), 4.5 / 12, 1e-12);
  ASSERT_EQ(r.windows.size(), 3u);
  EXPECT_EQ(r.windows[1].wall, "east");
  EXPECT_EQ(r.windows[0].frame_factor, 0.8);
  EXPECT_EQ(r.windows[2].wall, "roof");
  EXPECT_EQ(project_title("projects/office/project.yaml"), "office");
  EXPECT_EQ(project_title("studies/riverside_school.yaml"), "riverside_school");
}

TEST(ResultsModelBuilder, InteriorWindowsAreListedButNotOpenings) {
  project::Project p;
  project::RoomSpec office, corridor;
  office.name = "office";
  office.size_m = {4, 3, 3};
  corridor.name = "corridor";
  corridor.origin = {0, 3, 0};
  corridor.size_m = {4, 2, 3};
  project::WindowSpec outside;
  outside.name = "south";
  outside.wall = project::Wall::South;
  outside.width_m = 2;
  outside.height_m = 1;
  outside.sill_m = 1;
  outside.material = "glazing";
  project::WindowSpec inside = outside;
  inside.name = "to_corridor";
  inside.wall = project::Wall::North;
  office.windows = {outside, inside};
  p.geometry.rooms = {office, corridor};
  ASSERT_EQ(project::interior_windows(p.geometry).size(), 1u);
  CaseResult c;
  set_building(c, p, SceneDescription{});
  ASSERT_EQ(c.rooms.size(), 2u);
  const RoomSummary& r = c.rooms[0];
  ASSERT_EQ(r.windows.size(), 2u);
  EXPECT_EQ(r.windows[1].wall, "north (interior)");
  EXPECT_EQ(r.window_area_m2, 2);           // the south window only
  EXPECT_EQ(r.glazed_wall_area_m2, 4 * 3);  // the south wall only
  EXPECT_TRUE(c.rooms[1].windows.empty());
}

// The EN 17037 verdict says when it took the rule for horizontal openings (the target over
// 95 % of the area), so a reader of the report knows why a level did not pass.
TEST(ComplianceVerdicts, En17037SaysWhenItTookTheRuleForHorizontalOpenings) {
  GridResult windows = horizontal_grid(60, 5, 2, 1, 0.5);
  EXPECT_EQ(find(grid_verdicts(windows), "EN 17037", "level").reason, "minimum level reached");
  GridResult roof = windows;
  roof.annual->en17037_openings = "horizontal";
  roof.annual->en17037_target_area_required_percent = 95;
  const Verdict v = find(grid_verdicts(roof), "EN 17037", "level");
  EXPECT_NE(v.reason.find("horizontal openings: the target over 95 % of the area"), std::string::npos) << v.reason;
}

// LM-83-12 section 2.2.6 takes ASE "with all operable shading devices retracted" and sDA with
// the blinds operated hour by hour. A case with venetian blinds in place every hour gave both
// verdicts from the light through the slats: projects/blinds' `tilted` case (45 degrees) read
// ASE 0 % "pass" and LEED sDA 42.9 % "1 point", where the room's ASE without the blinds is
// 30 % (fail) and its operated sDA 25.7 % (0 points). Now: not assessed, naming the blinds;
// the operated result keeps its verdicts when its open case has no blinds, and loses them when
// it has (its ASE and its 2 % rule would be the sun through the slats).
TEST(ComplianceVerdicts, Lm83SdaAndAseAreNotAssessedWithBlindsInPlace) {
  const GridResult grid = horizontal_grid(42.9, 0, 2, 1, 0.5);
  for (const char* criterion : {"sDA", "ASE"}) {
    EXPECT_NE(find(grid_verdicts(grid), "IES", criterion).outcome, "not assessed") << criterion;
    const Verdict v = find(grid_verdicts(grid, {"venetian"}), "IES", criterion);
    EXPECT_EQ(v.outcome, "not assessed") << criterion;
    EXPECT_FALSE(v.value.has_value());
    EXPECT_NE(v.reason.find("blinds 'venetian' are in place every hour"), std::string::npos) << v.reason;
    EXPECT_NE(v.reason.find("operation"), std::string::npos) << v.reason;
  }
  EXPECT_EQ(find(grid_verdicts(grid), "LEED", "sDA").reason, "1 point");
  EXPECT_EQ(find(grid_verdicts(grid, {"venetian"}), "LEED", "sDA").outcome, "not assessed");
  // Neither the EN 17037 nor the BREEAM verdict depends on it.
  EXPECT_EQ(find(grid_verdicts(grid, {"venetian"}), "EN 17037", "level").outcome, "pass");
  EXPECT_EQ(find(grid_verdicts(grid, {"venetian"}), "BREEAM", "").outcome, "pass");
  // Through the model: the base with blinds, a variant without, the operated result of each.
  ResultsModel m;
  CaseResult base, raised, operated;
  base.kind = "base";
  base.blinds_in_place = {"venetian", "upper"};
  raised.kind = "variant";
  operated.kind = "operated";
  base.grids = raised.grids = operated.grids = {grid};
  m.cases = {base, raised, operated};
  assess_compliance(m);
  const Verdict b = find(m.cases[0].grids[0].verdicts, "IES", "ASE");
  EXPECT_EQ(b.outcome, "not assessed");
  EXPECT_NE(b.reason.find("blinds 'venetian' and 'upper'"), std::string::npos) << b.reason;
  EXPECT_EQ(find(m.cases[1].grids[0].verdicts, "IES", "ASE").outcome, "pass");
  EXPECT_EQ(find(m.cases[2].grids[0].verdicts, "LEED", "sDA").outcome, "pass");
  m.cases[2].blinds_in_place = {"venetian"};
  assess_compliance(m);
  const Verdict o = find(m.cases[2].grids[0].verdicts, "IES", "ASE");
  EXPECT_EQ(o.outcome, "not assessed");
  EXPECT_NE(o.reason.find("the open case has the blinds 'venetian'"), std::string::npos) << o.reason;
}

// set_building lists the case's enabled blinds, which the verdicts read; disabled blinds
// (raised) and other systems are not listed.
TEST(ResultsModelBuilder, BlindsInPlaceAreTheEnabledBlinds) {
  project::Project p;
  project::SystemSpec blinds, raised, shelf;
  blinds.name = "venetian";
  blinds.params = project::BlindsSpec{};
  raised = blinds;
  raised.name = "raised";
  raised.enabled = false;
  shelf.name = "shelf";
  shelf.params = project::LightShelfSpec{};
  p.geometry.systems = {shelf, blinds, raised};
  CaseResult c;
  set_building(c, p, SceneDescription{});
  EXPECT_EQ(c.blinds_in_place, std::vector<std::string>{"venetian"});
}

// A blind drawn as a material (a measured BSDF of a venetian blind, a roller shade as
// `translucent` with `shading: operable`) is operable shading in place as much as a `blinds`
// system: projects/bsdf_blind (a 45-degree blind BSDF in the window every hour) run as an annual
// study read "ASE 0 % pass" from the sun through its slats, where the room with clear glass has
// ASE 44 % (fail). Now not assessed, naming the material and why it counts.
TEST(ComplianceVerdicts, Lm83IsNotAssessedWithAnOperableShadingMaterialInPlace) {
  const GridResult grid = horizontal_grid(42.9, 0, 2, 1, 0.5);
  const std::vector<ShadingMaterialInPlace> blind = {{"blind", "its BSDF file's DeviceType is 'Venetian blind'"}};
  for (const char* criterion : {"sDA", "ASE"}) {
    const Verdict v = find(grid_verdicts(grid, {}, false, blind), "IES", criterion);
    EXPECT_EQ(v.outcome, "not assessed") << criterion;
    EXPECT_NE(v.reason.find("the operable shading material 'blind' (its BSDF file's DeviceType is 'Venetian blind') "
                            "is in place every hour"),
              std::string::npos)
        << v.reason;
  }
  EXPECT_EQ(find(grid_verdicts(grid, {}, false, blind), "LEED", "sDA").outcome, "not assessed");
  EXPECT_EQ(find(grid_verdicts(grid, {}, false, blind), "EN 17037", "level").outcome, "pass");
  // With blinds too, both are named; the operated result names its open case's.
  const Verdict both = find(grid_verdicts(grid, {"venetian"}, false, blind), "IES", "ASE");
  EXPECT_NE(both.reason.find("the blinds 'venetian' and the operable shading material 'blind'"), std::string::npos)
      << both.reason;
  ResultsModel m;
  CaseResult operated;
  operated.kind = "operated";
  operated.grids = {grid};
  operated.shading_materials_in_place = blind;
  m.cases = {operated};
  assess_compliance(m);
  const Verdict o = find(m.cases[0].grids[0].verdicts, "IES", "ASE");
  EXPECT_EQ(o.outcome, "not assessed");
  EXPECT_NE(o.reason.find("the open case has the operable shading material 'blind'"), std::string::npos) << o.reason;
}
