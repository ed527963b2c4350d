#!/usr/bin/env bash
# CLI golden tests: run the real binary ($DAYPHOTON) from the repository root on the cases
# below and compare exit code + combined stdout/stderr with tests/cli/golden/<name>.out.
# UPDATE=1 rewrites the golden files (review the diff before committing).
set -u
cd "$(dirname "$0")/../.."
bin=${DAYPHOTON:?set DAYPHOTON to the dayphoton executable}
golden=tests/cli/golden
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
passed=0
failed=0

# check_case NAME EXPECTED_EXIT ARGS...
check_case() {
  local name=$1 expected=$2
  shift 2
  local out="$scratch/$name.out"
  "$bin" "$@" >"$out" 2>&1
  local code=$?
  echo "exit $code" >>"$out"
  if [ "${UPDATE:-0}" = 1 ]; then cp "$out" "$golden/$name.out"; fi
  if [ "$code" -ne "$expected" ]; then
    echo "FAIL $name: exit $code, expected $expected"; cat "$out"; failed=$((failed + 1)); return
  fi
  if ! diff -u "$golden/$name.out" "$out"; then
    echo "FAIL $name: output differs from $golden/$name.out"; failed=$((failed + 1)); return
  fi
  echo "ok   $name"; passed=$((passed + 1))
}

check_case version 0 --version
check_case help 0 --help
check_case check_office 0 check projects/office/project.yaml
check_case check_roof_light 0 check projects/roof_light/project.yaml
check_case check_corridor 0 check projects/corridor/project.yaml
check_case check_black_room 0 check tests/cli/cases/black_room.yaml
check_case check_black_room_surface 1 check tests/cli/cases/black_room_surface.yaml
check_case check_typos 1 check tests/cli/cases/typos.yaml
check_case check_window_too_big 1 check tests/cli/cases/window_too_big.yaml
check_case check_radiance_office 0 check tests/cli/cases/radiance_office.yaml
check_case check_radiance_errors 1 check tests/cli/cases/radiance_errors.yaml
check_case check_variant_window_too_big 1 check tests/cli/cases/variant_window_too_big.yaml
check_case check_yaml_syntax 1 check tests/cli/cases/syntax.yaml
check_case check_daylight_factor_only 0 check tests/cli/cases/daylight_factor_only.yaml
check_case check_daylight_factor_study 0 check tests/cli/cases/daylight_factor_study.yaml
check_case check_points_in_time 0 check tests/cli/cases/points_in_time.yaml
check_case check_points_in_time_sun_set 1 check tests/cli/cases/points_in_time_sun_set.yaml
check_case check_site_other_time_zone 1 check tests/cli/cases/site_other_time_zone.yaml
check_case check_site_far_from_station 0 check tests/cli/cases/site_far_from_station.yaml
check_case check_site_from_weather 0 check tests/cli/cases/site_from_weather.yaml
check_case check_glazing 0 check tests/cli/cases/glazing.yaml
check_case check_roof_light_polygons 0 check tests/cli/cases/roof_light_polygons.yaml
check_case check_honeybee 0 check projects/honeybee/project.yaml
check_case check_honeybee_bad 1 check tests/cli/cases/honeybee_bad.yaml
check_case check_missing_file 1 check tests/cli/cases/does_not_exist.yaml
check_case check_school_occupancy 0 check tests/cli/cases/school/project.yaml
check_case check_occupancy_short_csv 1 check tests/cli/cases/occupancy_short.yaml
check_case usage_no_subcommand 2
check_case sun_bad_epw 1 sun tests/cli/cases/truncated.epw
check_case check_weather_wea 0 check tests/cli/cases/weather_wea.yaml
check_case sun_wea 0 sun tests/data/weather/hourly.wea
check_case sun_wea_missing_hour 1 sun tests/data/weather/missing_hour.wea
check_case sun_epw_variants_warn 0 sun tests/data/weather/ladybug_style.epw -o "$scratch/variants_sun.csv"
check_case sun_epw_unused_fields_warn 0 sun tests/data/weather/unused_fields_junk.epw -o "$scratch/junk_sun.csv"
check_case sky_epw_long_gap 1 sky tests/data/weather/missing_long_gap.epw -o "$scratch/gap.mtx"
check_case sky_bad_cie_type 2 sky --cie 19
check_case sky_conflicting_options 2 sky projects/office/USA_CA_Oakland.Intl.AP.724930_TMY3.epw --cie overcast
check_case sky_overcast_vector 0 sky --cie overcast --illuminance 10000

# run on an invalid project: located errors, exit 1, nothing written.
rm -rf "$scratch/results"
check_case run_invalid_project 1 run tests/cli/cases/typos.yaml --output "$scratch/results" --quiet
if [ -e "$scratch/results" ]; then echo "FAIL run wrote $scratch/results"; failed=$((failed + 1)); fi

# Every bad project file of tests/data/bad/ (README.md there): check exits 1 and prints the
# first expected message located as file:line:col (the full lists: tests/project/bad_inputs_test.cpp).
bad_failed=$failed
for f in tests/data/bad/*.yaml; do
  expect=$(grep -a -m1 '^# expect: ' "$f" | sed 's/^# expect: //')
  where=${expect%%: *}
  wanted="$f:$where: error: ${expect#*: }"
  "$bin" check "$f" >"$scratch/bad.out" 2>&1
  code=$?
  if [ -n "$expect" ] && [ "$code" -eq 1 ] && grep -qxF -- "$wanted" "$scratch/bad.out"; then
    passed=$((passed + 1))
  else
    echo "FAIL check $f: exit $code, expected 1 and the line: $wanted"; cat -v "$scratch/bad.out"; failed=$((failed + 1))
  fi
done
if [ "$failed" -eq "$bad_failed" ]; then echo "ok   check on each of tests/data/bad/*.yaml"; fi

# run refuses a grid name that leaves the output folder: exit 1, nothing written anywhere.
mkdir -p "$scratch/escape/project"
cp tests/data/bad/grid_name_parent.yaml "$scratch/escape/project/project.yaml"
"$bin" run "$scratch/escape/project/project.yaml" --quiet >"$scratch/escape.out" 2>&1
code=$?
if [ "$code" -eq 1 ] && [ "$(find "$scratch/escape" -mindepth 1 | wc -l)" -eq 2 ]; then
  echo "ok   run_grid_name_escape"; passed=$((passed + 1))
else
  echo "FAIL run_grid_name_escape: exit $code"; find "$scratch/escape"; failed=$((failed + 1))
fi

# Several projects with --output write to --output/<folder name>: two folders of one name
# (here: the same folder twice) would share it; exit 2 before anything runs.
"$bin" run projects/office/project.yaml ./projects/office/project.yaml --output "$scratch/two" --quiet \
  >"$scratch/two.out" 2>&1
code=$?
if [ "$code" -eq 2 ] && grep -q "would both write to" "$scratch/two.out" && [ ! -e "$scratch/two" ]; then
  echo "ok   run_two_projects_one_folder"; passed=$((passed + 1))
else
  echo "FAIL run_two_projects_one_folder: exit $code"; cat "$scratch/two.out"; failed=$((failed + 1))
fi

# A cache that cannot be written (its folder is a file: ENOTDIR, even as root) fails every
# photon artefact's write while other sources are still being traced: a clean error and
# exit 4, never a signal (the cancelled photon passes used to segfault: exit 139).
: >"$scratch/.nocache-cache"
"$bin" run projects/office/project.yaml --output "$scratch/nocache" --threads 4 --quiet >"$scratch/nocache.out" 2>&1
code=$?
if [ "$code" -eq 4 ] &&
   grep -qxF "dayphoton: error: cannot create the cache folder $scratch/.nocache-cache: Not a directory" "$scratch/nocache.out"; then
  echo "ok   run_cache_not_writable"; passed=$((passed + 1))
else
  echo "FAIL run_cache_not_writable: exit $code"; cat "$scratch/nocache.out"; failed=$((failed + 1))
fi

# A sensor inside a solid without drop_occluded: run stops before it writes anything.
sed 's/, drop_occluded: true//' tests/cli/cases/roof_light_polygons.yaml >"$scratch/column.yaml"
"$bin" run "$scratch/column.yaml" --output "$scratch/column_results" --quiet >"$scratch/column.out" 2>&1
code=$?
if [ "$code" -eq 1 ] && [ ! -e "$scratch/column_results" ] &&
   grep -q "column.yaml:31:7: error: sensor set 'workplane': 1 of 64 sensors lie inside a solid" "$scratch/column.out"; then
  echo "ok   run_sensor_in_column"; passed=$((passed + 1))
else
  echo "FAIL run_sensor_in_column: exit $code"; cat "$scratch/column.out"; failed=$((failed + 1))
fi

# drop_occluded: run leaves out the sensor in the column and the probe above the roof, and
# says so in run.log and summary.json (dropped_sensors) and the results hold the rest.
"$bin" run tests/cli/cases/roof_light_polygons.yaml --output "$scratch/roof" --quiet >"$scratch/roof.out" 2>&1
code=$?
if [ "$code" -eq 0 ] && grep -q '"dropped_sensors"' "$scratch/roof/summary.json" &&
   grep -q "sensor set 'workplane': 1 of 64 sensors lie inside a solid" "$scratch/roof/run.log" &&
   grep -q "sensor set 'probes': 1 of 2 sensors lie outside every room" "$scratch/roof/run.log" &&
   [ "$(wc -l <"$scratch/roof/workplane/sensors.csv")" -eq 64 ] && [ "$(wc -l <"$scratch/roof/probes/sensors.csv")" -eq 2 ]; then
  echo "ok   run_drop_occluded"; passed=$((passed + 1))
else
  echo "FAIL run_drop_occluded: exit $code"; cat "$scratch/roof.out"; failed=$((failed + 1))
fi

# study: daylight_factor with a weather file: no sky matrix, no sun step, no annual output.
"$bin" run tests/cli/cases/daylight_factor_study.yaml --output "$scratch/df_study" --quiet >"$scratch/df_study.out" 2>&1
code=$?
if [ "$code" -eq 0 ] && [ -s "$scratch/df_study/workplane/daylight_factor.csv" ] &&
   [ -s "$scratch/df_study/workplane/coefficients_sky.mtx" ] &&
   [ ! -e "$scratch/df_study/workplane/coefficients_sun.mtx" ] && [ ! -e "$scratch/df_study/workplane/illuminance.csv" ] &&
   ! grep -qE "^(sky matrix|sun |direct sun|annual)" "$scratch/df_study/run.log" &&
   grep -q '"study": "daylight_factor"' "$scratch/df_study/summary.json" &&
   grep -q '"weather": ""' "$scratch/df_study/summary.json" &&
   grep -q "study: daylight factors under the CIE overcast sky" "$scratch/df_study/run.log"; then
  echo "ok   run_daylight_factor_study"; passed=$((passed + 1))
else
  echo "FAIL run_daylight_factor_study: exit $code"; cat "$scratch/df_study.out" "$scratch/df_study/run.log"; failed=$((failed + 1))
fi

# annual --sky-vector: the CIE overcast sky of `dayphoton sky` applied to the exported sky
# coefficients gives DF x E_h / 100 at every sensor (the run's DF sky is the same sky), up to
# the DF's sky component, which the run takes from the continuous sky instead of the patches
# (docs/outputs.md, daylight_factor.csv): within 3 % here (its largest share, a few per cent
# deep in a room); another sky level (8950 lx) would miss by 11 %.
"$bin" sky --cie overcast --illuminance 10000 -o "$scratch/overcast.mtx" &&
"$bin" annual --coefficients "$scratch/df_study/workplane" --sky-vector "$scratch/overcast.mtx" -o "$scratch/sv" --quiet 2>"$scratch/sv.err"
# ... and says on stderr, even with --quiet, that the product is patch-uniform.
if grep -q "^note: .*coefficients_sky.mtx: the coefficients times one sky vector is the patch-uniform product" "$scratch/sv.err" &&
   python3 - "$scratch/df_study/workplane/daylight_factor.csv" "$scratch/sv/sky_vector_illuminance.csv" <<'PY'
import csv, sys
df = [float(r["df_percent"]) for r in csv.DictReader(open(sys.argv[1]))]
lux = [float(r["illuminance_lux"]) for r in csv.DictReader(open(sys.argv[2]))]
# DF printed with 4 decimals (0.5e-4 % of 10000 lx = 0.005 lx), lux with 1 (0.05 lx).
sys.exit(0 if len(df) == len(lux) > 0 and all(abs(e - 100 * d) <= 0.03 * 100 * d + 0.06 for d, e in zip(df, lux)) else 1)
PY
then
  echo "ok   annual_sky_vector"; passed=$((passed + 1))
else
  echo "FAIL annual_sky_vector"; cat "$scratch/sv.err"; failed=$((failed + 1))
fi

# The cache lies beside the output folder, not in it; `clean` keeps what the last run used.
if [ -d "$scratch/.df_study-cache" ] && [ ! -e "$scratch/df_study/.cache" ] &&
   [ -s "$scratch/.df_study-cache/used-by-last-run.txt" ] &&
   "$bin" clean "$scratch/df_study" --dry-run | grep -q "^would remove 0 artefacts (0.0 MB) that the last complete run did not use; kept 147 " &&
   "$bin" clean "$scratch/df_study" --all | grep -q "^removed $scratch/.df_study-cache: 148 files" && [ ! -e "$scratch/.df_study-cache" ]; then
  echo "ok   run_cache_beside_and_clean"; passed=$((passed + 1))
else
  echo "FAIL run_cache_beside_and_clean"; ls -a "$scratch"; failed=$((failed + 1))
fi

# A project in a folder whose name is not UTF-8 (Latin-1 'cafe' with an acute accent): the run
# completes and its JSON files are UTF-8 (the bad byte replaced), instead of exit 4 from the
# JSON writer at the very end.
latin1="$scratch/$(printf 'caf\351')"
mkdir -p "$latin1" && cp tests/cli/cases/daylight_factor_only.yaml "$latin1/project.yaml"
"$bin" run "$latin1/project.yaml" --quiet >"$scratch/latin1.out" 2>&1
code=$?
if [ "$code" -eq 0 ] && iconv -f UTF-8 -t UTF-8 "$latin1/results/summary.json" >/dev/null 2>&1; then
  echo "ok   run_folder_name_not_utf8"; passed=$((passed + 1))
else
  echo "FAIL run_folder_name_not_utf8: exit $code"; cat "$scratch/latin1.out"; failed=$((failed + 1))
fi
# The same run is a daylight-factor study without a weather file (`check` of it passes:
# check_daylight_factor_only above): no sky matrix, sun or annual step in its log, and none in
# its typed step list (timings.json), which has the photons and coefficients (one step, the
# accuracy rounds, at the default accuracy target).
if [ "$code" -eq 0 ] && ! grep -qE "^(sky matrix|sun |direct sun|annual|time: (sky matrix|sun|direct sun|annual))" "$latin1/results/run.log" &&
   python3 - "$latin1/results/timings.json" <<'PY'
import json, sys
names = [s["name"] for s in json.load(open(sys.argv[1]))["steps"]]
assert ("photons" in names and "coefficients workplane" in names) or "photons (accuracy rounds)" in names, names
assert not [n for n in names if n.startswith(("sky matrix", "sun", "direct sun", "annual"))], names
PY
then
  echo "ok   run_daylight_factor_only_no_sun_step"; passed=$((passed + 1))
else
  echo "FAIL run_daylight_factor_only_no_sun_step"; cat "$latin1/results/run.log"; failed=$((failed + 1))
fi

# The accuracy target with sun bins in an annual run (tests/cli/cases/accuracy_sun.yaml, the
# draft preset): results.json's typed accuracy of the sky and of the sun bins equals
# summary.json's, and report.html states both in words with those numbers at the report's
# precision (docs/report.md "uncertainty").
"$bin" run tests/cli/cases/accuracy_sun.yaml --output "$scratch/accuracy_sun" --quiet >"$scratch/accuracy_sun.out" 2>&1
code=$?
if [ "$code" -eq 0 ] && python3 - "$scratch/accuracy_sun" <<'PY'
import json, sys
d = sys.argv[1]
grid = json.load(open(d + "/results.json"))["cases"][0]["grids"][0]
summary = json.load(open(d + "/summary.json"))["grids"][0]["accuracy"]
sky, sun, ssun = grid["daylight_factor"]["accuracy"], grid["sun_accuracy"], summary["sun"]
assert sky == {"target_percent": summary["target_df_relative_stderr_percent"],
               "reached_percent": summary["reached_df_relative_stderr_percent"], "rounds": summary["rounds"],
               "photons": summary["photons"], "stop_reason": summary["stop_reason"], "status": summary["status"],
               "direct_samples_per_bin": summary["direct_samples_per_bin"]}, sky
assert sun == {"target_percent": ssun["target_relative_stderr_percent"],
               "reached_percent": ssun["reached_relative_stderr_percent"],
               "hourly_percent": ssun["hourly_relative_stderr_percent"], "rounds": ssun["rounds"],
               "photons": ssun["photons"], "stop_reason": ssun["stop_reason"], "status": ssun["status"]}, sun
def pct(v):  # the report's DF precision: 0.1 from 1 up, 2 significant digits below
    return f"{v:.1f}" if v >= 1 else f"{v:.2g}"
def photons(n):
    return f"{n / 1e6:.1f} million" if n >= 1e6 else f"{n:,}".replace(",", " ")
def rounds(n):
    return f"{n} round" + ("" if n == 1 else "s")
html = open(d + "/report.html").read()
for part, a in (("sky", sky), ("sun", sun)):
    start = html.index(f'<li class="accuracy" data-part="{part}" data-case="base" data-grid="desks">')
    item = html[start:html.index("</li>", start)]
    expect = (f"the target is a relative standard error of at most {pct(a['target_percent'])} % at the 95th "
              f"percentile of the sensors (19 sensors in 20 are at or below it). Reached {pct(a['reached_percent'])} % "
              f"after {rounds(a['rounds'])} of photon tracing ({photons(a['photons'])} photons). ")
    assert expect in item, (expect, item)
    assert ("Target met." in item) == (a["status"] == "met"), item
sun_item = html[html.index('data-part="sun"'):]
assert f"One hour's sun-bin value carries more: {pct(sun['hourly_percent'])} %" in sun_item, sun_item[:600]
PY
then
  echo "ok   run_accuracy_sun_bins_reported"; passed=$((passed + 1))
else
  echo "FAIL run_accuracy_sun_bins_reported: exit $code"; cat "$scratch/accuracy_sun.out"; failed=$((failed + 1))
fi

# annual: recomputes tables and metrics from exported coefficients (a synthetic 2-sensor grid).
EPW=projects/office/USA_CA_Oakland.Intl.AP.724930_TMY3.epw
check_case annual_missing_folder 1 annual --coefficients tests/cli/cases/does_not_exist --weather $EPW
check_case annual_no_grid_folders 1 annual --coefficients tests/cli/cases/school --weather $EPW
check_case annual_basis_mismatch 1 annual --coefficients tests/cli/cases/annual_grid --weather $EPW --basis reinhart:2
check_case annual_bad_basis 2 annual --coefficients tests/cli/cases/annual_grid --weather $EPW --basis klems
check_case annual_sky_matrix_not_a_matrix 1 annual --coefficients tests/cli/cases/annual_grid --weather $EPW --sky-matrix tests/cli/cases/annual_grid/sensors.csv
"$bin" annual --coefficients tests/cli/cases/annual_grid --weather $EPW -o "$scratch/annual" --illuminance-csv --quiet
# Without --illuminance-csv the hourly table is written in binary only (docs/outputs.md).
"$bin" annual --coefficients tests/cli/cases/annual_grid --weather $EPW -o "$scratch/annual_binary" --quiet
if [ "$(wc -l <"$scratch/annual/illuminance.csv")" -eq 8761 ] && [ -s "$scratch/annual/illuminance.bin" ] && [ -s "$scratch/annual/grid_metrics.json" ] &&
   [ ! -e "$scratch/annual_binary/illuminance.csv" ] && cmp -s "$scratch/annual/illuminance.bin" "$scratch/annual_binary/illuminance.bin"; then
  echo "ok   annual_tables"; passed=$((passed + 1))
else
  echo "FAIL annual_tables"; failed=$((failed + 1))
fi

# annual --weather with a part-year file warns as check and run do (study::partial_year_message,
# on stderr even with --quiet); a whole-year file does not.
"$bin" annual --coefficients tests/cli/cases/annual_grid --weather tests/data/weather/hourly.wea -o "$scratch/annual_part" \
  --quiet 2>"$scratch/annual_part.err"
code=$?
"$bin" annual --coefficients tests/cli/cases/annual_grid --weather $EPW -o "$scratch/annual_whole" --quiet \
  2>"$scratch/annual_whole.err"
if [ "$code" -eq 0 ] && grep -qF "warning: the weather file tests/data/weather/hourly.wea holds 48 hourly records (1/1 to 1/2), not a whole year of 8760: the annual metrics count these records only" "$scratch/annual_part.err" &&
   ! grep -q "not a whole year" "$scratch/annual_whole.err"; then
  echo "ok   annual_part_year_warning"; passed=$((passed + 1))
else
  echo "FAIL annual_part_year_warning (exit $code)"; cat "$scratch/annual_part.err" "$scratch/annual_whole.err"; failed=$((failed + 1))
fi

# sun: one row per record plus the header, written atomically to -o.
"$bin" sun projects/office/USA_CA_Oakland.Intl.AP.724930_TMY3.epw -o "$scratch/sun.csv"
rows=$(wc -l <"$scratch/sun.csv")
if [ "$rows" -eq 8761 ] && ! ls "$scratch" | grep -q '\.tmp\.'; then
  echo "ok   sun_table"; passed=$((passed + 1))
else
  echo "FAIL sun_table: $rows lines"; failed=$((failed + 1))
fi

# sky: the gendaymtx-compatible annual matrix reads back with the right shape.
"$bin" sky projects/office/USA_CA_Oakland.Intl.AP.724930_TMY3.epw --solar-position radiance --format float \
  -o "$scratch/sky.mtx"
if head -c 300 "$scratch/sky.mtx" | grep -qa "NROWS=146" && head -c 300 "$scratch/sky.mtx" | grep -qa "NCOLS=8760"; then
  echo "ok   sky_matrix"; passed=$((passed + 1))
else
  echo "FAIL sky_matrix"; failed=$((failed + 1))
fi

# report: report.html from a finished run's folder (a two-sensor results folder with its
# results.json, no images so nothing is written into the source tree); errors are located
# (exit 1) or usage (exit 2).
check_case report_help 0 report --help
check_case report_missing_folder 1 report tests/cli/cases/does_not_exist --no-images
check_case report_bad_sky_hour 2 report tests/cli/cases/report_results --sky-hour 13/1/12
# A results folder of a dayphoton before results.json: a located error that says to run again.
check_case report_old_results 1 report tests/cli/cases/report_old_results --no-images
"$bin" report tests/cli/cases/report_results --no-images -o "$scratch/report.html" --quiet
if grep -q 'id="grid-grid-df"' "$scratch/report.html" && grep -q 'data-sections="summary verdicts building variants grid-grid' "$scratch/report.html" &&
   ! ls tests/cli/cases/report_results | grep -q -e report.html -e '\.exr$'; then
  echo "ok   report_html"; passed=$((passed + 1))
else
  echo "FAIL report_html"; failed=$((failed + 1))
fi

# render: usage errors are found before any photon is traced; a tiny rendering of the office
# writes a finite EXR and a PNG.
check_case render_help 0 render --help
check_case render_bad_view 2 render projects/office/project.yaml --view 1,2 --direction 0,1,0 -o "$scratch/v.exr"
check_case render_bad_sky 2 render projects/office/project.yaml --view 3,4,1.2 --direction 0,1,0 --sky cloudy -o "$scratch/v.exr"
check_case render_not_exr 2 render projects/office/project.yaml --view 3,4,1.2 --direction 0,1,0 -o out.png
check_case render_parallel_up 2 render projects/office/project.yaml --view 3,4,1.2 --direction 0,0,1 -o "$scratch/v.exr"
check_case render_missing_project 1 render tests/cli/cases/does_not_exist.yaml --view 3,4,1.2 --direction 0,1,0 -o "$scratch/v.exr"
"$bin" render projects/office/project.yaml --view 3,7.5,1.4 --direction 0,-1,-0.2 --fov 70 --width 32 --height 24 \
  --samples 1 --direct-samples 2 --photons 300 -o "$scratch/office.exr" --quiet
if [ "$(head -c 4 "$scratch/office.exr" | od -An -tx1 | tr -d ' \n')" = "762f3101" ] &&
   [ "$(head -c 8 "$scratch/office.png" | od -An -tx1 | tr -d ' \n')" = "89504e470d0a1a0a" ]; then
  echo "ok   render_office"; passed=$((passed + 1))
else
  echo "FAIL render_office"; failed=$((failed + 1))
fi

# A diffusing port is drawn with its own luminance (tau E / pi from its sky side): the
# rendering runs without a warning (tests/engine/renderer_test.cpp checks the luminance).
mkdir -p "$scratch/frosted" && cp projects/office/*.epw "$scratch/frosted/" &&
sed '/^  glazing:$/,/^    transmittance:/c\  glazing: {type: translucent, reflectance: 0.1, transmissivity: 0.6, transmitted_specular: 0}' \
  projects/office/project.yaml >"$scratch/frosted/project.yaml"
"$bin" render "$scratch/frosted/project.yaml" --view 3,7.5,1.4 --direction 0,-1,-0.2 --fov 70 --width 8 --height 6 \
  --samples 1 --direct-samples 1 --photons 100 -o "$scratch/frosted.exr" --quiet 2>"$scratch/frosted.err"
code=$?
if [ "$code" -eq 0 ] && [ "$(head -c 4 "$scratch/frosted.exr" | od -An -tx1 | tr -d ' \n')" = "762f3101" ] &&
   ! grep -q "^warning:" "$scratch/frosted.err"; then
  echo "ok   render_diffusing_port"; passed=$((passed + 1))
else
  echo "FAIL render_diffusing_port: exit $code"; cat "$scratch/frosted.err"; failed=$((failed + 1))
fi

echo "cli: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
