# What the mpirun tests of dayphoton share, sourced by them (functions only; nothing runs
# when it is sourced). A test sets `mpiexec` (and `dayphoton`, for the kill tests' and the
# other ranks' functions) from its arguments, calls mpi_test_begin, and uses the rest as it needs. Each
# function returns non-zero (or calls the test's own `fail`) when its check fails, so every
# test can still fail.

# The environment of every mpirun here, a scratch folder $tmp removed on exit (with the mpirun
# in $job, if a test left one running when a check failed early: only the mpirun started
# here), and the flags of every mpirun in the array $mpirun_flags.
mpi_test_begin() {
  # Open MPI refuses to run as root without the first two (mpirun(1), --allow-run-as-root);
  # one machine needs no network interfaces (and containers without them stay quiet).
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl=self,vader
  # Open MPI binds each rank to one core by default when there are at most 2 ranks, which
  # leaves TBB one thread; the ranks here share the machine's cores (docs/cluster.md), and
  # 3 ranks oversubscribe a 2-core machine.
  mpirun_flags=(--oversubscribe --bind-to none)
  tmp=$(mktemp -d)
  job=
  trap mpi_test_end EXIT
}

mpi_test_end() {
  [ -n "${job:-}" ] && kill -9 "$job" 2>/dev/null
  rm -rf "$tmp"
}

# `mpi_run SECONDS NP COMMAND...`: COMMAND under `mpirun -np NP`, killed after SECONDS.
mpi_run() {
  local seconds=$1 np=$2
  shift 2
  timeout "$seconds" "$mpiexec" -np "$np" "${mpirun_flags[@]}" "$@"
}

# The side-lit room's materials, geometry and sensors, the YAML the two rooms below share.
side_lit_room_body() {
  cat <<'YAML'
materials:
  walls: {type: lambertian, reflectance: 0.5}
  glass: {type: glass, transmittance: 0.6}
geometry:
  rooms:
    - name: office
      size: [4, 5, 3]
      materials: {floor: walls, ceiling: walls, walls: walls}
      windows: [{name: w, wall: south, width: 3, height: 1.5, sill: 0.9, material: glass}]
sensors:
  grids:
    - {name: workplane, room: office, height: 0.8, spacing: 0.5}
YAML
}

# `side_lit_room FILE SIMULATION`: a daylight-factor study of a 4 x 5 x 3 m side-lit room (a
# 3 x 1.5 m south window, 80 work-plane sensors at 0.5 m), no pictures and no report, with
# the line SIMULATION (one mapping, e.g. "photons_per_bin: 4000") as its `simulation:`.
side_lit_room() {
  cat > "$1" <<YAML
version: 1
study: daylight_factor
site: {latitude: 51.5, longitude: -0.12, time_zone: 0}
$(side_lit_room_body)
simulation:
  $2
outputs:
  images: false
  report: false
YAML
}

# `sun_room FOLDER SOURCE_DIR TARGET_PERCENT`: the side-lit room's annual study in Oakland
# (projects/office's weather file copied beside it) with `sun: bins` on Reinhart MF 1 (85 bins,
# 63 lit) and `simulation.accuracy` at TARGET_PERCENT, written to FOLDER/project.yaml, no
# pictures and no report. Returns non-zero, saying so, if the weather file is missing.
sun_room() {
  local folder=$1 source_dir=$2
  mkdir -p "$folder"
  cp "$source_dir/projects/office/USA_CA_Oakland.Intl.AP.724930_TMY3.epw" "$folder/weather.epw" ||
    { echo "no weather file in $source_dir/projects/office"; return 1; }
  cat > "$folder/project.yaml" <<YAML
version: 1
site: {latitude: 37.72, longitude: -122.22, time_zone: -8}
weather: weather.epw
$(side_lit_room_body)
simulation:
  sun: bins
  sun_mf: 1
  accuracy: {target_df_relative_stderr_percent: $3}
outputs:
  images: false
  report: false
YAML
}

# `office_copy SOURCE_DIR FOLDER`: projects/office (project file and weather file) copied to
# FOLDER at a fortieth of its photons (which changes nothing but the noise), with float
# matrices and no pictures or report: the same steps, a third of the time of the files.
# Returns non-zero, saying so, if a line it changes was not found.
office_copy() {
  local source_dir=$1 folder=$2
  mkdir -p "$folder"
  cp "$source_dir/projects/office/project.yaml" "$source_dir/projects/office/"*.epw "$folder/"
  sed -i 's/^  photons_per_bin: 40000$/  photons_per_bin: 1000/; s/^  matrix_format: ascii$/  matrix_format: float/;
          s/^  images: true$/  images: false/; s/^  report: true$/  report: false/' "$folder/project.yaml"
  grep -q '^  photons_per_bin: 1000$' "$folder/project.yaml" && grep -q '^  matrix_format: float$' "$folder/project.yaml" &&
    grep -q '^  images: false$' "$folder/project.yaml" && grep -q '^  report: false$' "$folder/project.yaml" ||
    { echo "office: photons_per_bin, matrix_format, images or report not found"; return 1; }
}

# `office_variants_copy SOURCE_DIR FOLDER`: projects/office_variants' project file copied to
# FOLDER at a quarter of its photons, with float matrices and no pictures or report. Its
# weather file is ../office/'s: FOLDER's sibling office/ must hold it (office_copy). Returns
# non-zero, saying so, if a line it changes was not found.
office_variants_copy() {
  local source_dir=$1 folder=$2
  mkdir -p "$folder"
  cp "$source_dir/projects/office_variants/project.yaml" "$folder/"
  sed -i 's/^  photons_per_bin: 2000$/  photons_per_bin: 500/; s/^  matrix_format: ascii$/  matrix_format: float\n  images: false\n  report: false/' \
    "$folder/project.yaml"
  grep -q '^  photons_per_bin: 500$' "$folder/project.yaml" && grep -q '^  images: false$' "$folder/project.yaml" ||
    { echo "office_variants: photons_per_bin or matrix_format not found"; return 1; }
}

# `same_results REFERENCE OUT`: whether the results folders hold the same bytes, apart from
# run.log and timings.json (times) and the output folder's name in summary.json. Prints the
# files that differ.
same_results() {
  local reference=$1 out=$2 same=0
  diff -r -q -x run.log -x timings.json -x summary.json "$reference" "$out" || same=1
  cmp -s <(sed "s|$reference|OUT|g" "$reference/summary.json") <(sed "s|$out|OUT|g" "$out/summary.json") ||
    { echo "summary.json differs (apart from the folder's name)"; same=1; }
  return $same
}

# `same_cache REFERENCE CACHE`: whether two cache folders hold the same artefacts (file names
# are content keys) and the same list of those the run used. Prints the first differences.
same_cache() {
  diff -r -q "$1" "$2" > /dev/null && return 0
  diff -r -q "$1" "$2" | head -5
  return 1
}

# `rank_pid MPIRUN_PID RANK`: the pid of that rank of the mpirun, its child whose environment
# says so.
rank_pid() {
  local child
  for child in $(ps -o pid= --ppid "$1"); do
    if tr '\0' '\n' <"/proc/$child/environ" 2>/dev/null | grep -qx "OMPI_COMM_WORLD_RANK=$2"; then
      echo "$child"
      return 0
    fi
  done
  return 1
}

# `start_run_to_kill PROJECT OUT CACHE LOG`: dayphoton run of PROJECT into OUT and CACHE under
# `mpirun -np 2` in the background, its output in LOG, mpirun's pid in $job (no time-out: the
# test kills one of its ranks).
start_run_to_kill() {
  "$mpiexec" -np 2 "${mpirun_flags[@]}" "$dayphoton" run "$1" --output "$2" --cache "$3" --quiet >"$4" 2>&1 &
  job=$!
}

# `await_in_job VICTIM LOG WHAT COMMAND...`: polls COMMAND (its stderr dropped: the file it
# looks at may not exist yet) every 0.02 s until it succeeds while
# the mpirun $job runs, for up to 120 s; calls `fail` if the run ends first (with its LOG) or
# the time is up. WHAT names the awaited event in those messages.
await_in_job() {
  local victim=$1 log=$2 what=$3 i
  shift 3
  for ((i = 0; i < 6000; ++i)); do
    "$@" 2>/dev/null && return 0
    kill -0 "$job" 2>/dev/null || fail "rank $victim: the run ended before $what: $(cat "$log")"
    sleep 0.02
  done
  fail "rank $victim: no $what after 120 s"
}

# `kill_rank_expect_incomplete VICTIM OUT`: kills rank VICTIM of the mpirun $job by SIGKILL;
# calls `fail` unless mpirun then exits non-zero within 60 s and the results folder OUT is
# marked incomplete (INCOMPLETE present, no summary.json). Sets $rc (mpirun's exit code) and
# $elapsed (seconds from the kill to the exit), and clears $job.
kill_rank_expect_incomplete() {
  local victim=$1 out=$2 pid start
  pid=$(rank_pid "$job" "$victim") || fail "rank $victim: its process was not found among mpirun's children"
  kill -9 "$pid"
  start=$(date +%s)
  while kill -0 "$job" 2>/dev/null && [ $(($(date +%s) - start)) -lt 60 ]; do sleep 0.05; done
  kill -0 "$job" 2>/dev/null && fail "rank $victim killed: mpirun still runs after 60 s"
  wait "$job"
  rc=$?
  job=
  elapsed=$(($(date +%s) - start))
  [ $rc -ne 0 ] || fail "rank $victim killed: mpirun exited 0"
  [ -e "$out/summary.json" ] && fail "rank $victim killed: the results folder has a summary.json (marked complete)"
  [ -e "$out/INCOMPLETE" ] || fail "rank $victim killed: the results folder has no INCOMPLETE marker"
}

# `rerun_completes VICTIM PROJECT OUT CACHE REFERENCE`: re-runs PROJECT under `mpirun -np 2`
# into the killed run's OUT and CACHE; calls `fail` unless it succeeds, removes INCOMPLETE and
# writes the uninterrupted run's results (same_results against REFERENCE).
rerun_completes() {
  local victim=$1 project=$2 out=$3 cache=$4 reference=$5
  mpi_run 300 2 "$dayphoton" run "$project" --output "$out" --cache "$cache" --quiet >"$tmp/rerun$victim.log" 2>&1 ||
    fail "rank $victim: the re-run failed: $(cat "$tmp/rerun$victim.log")"
  [ -e "$out/INCOMPLETE" ] && fail "rank $victim: the re-run left INCOMPLETE"
  same_results "$reference" "$out" || fail "rank $victim: the re-run wrote other results than the uninterrupted run"
}

# `other_ranks_wrapper`: writes $tmp/rank.sh, the command to start under mpirun in place of
# $dayphoton where the ranks other than 0 must write nothing (the writer flag, study_runner.h).
# Rank 0 runs dayphoton as given; every other rank runs it with TMPDIR a file,
# $tmp/not-a-folder (anything that made a temporary folder fails), in a working folder of its
# own, $tmp/cwd-rank<N>, and with "-rank<N>" appended to the folders of --output and --cache.
# other_ranks_wrote_nothing checks afterwards that none of them gained a file.
other_ranks_wrapper() {
  echo "not a folder" > "$tmp/not-a-folder"
  cat > "$tmp/rank.sh" <<EOF
#!/usr/bin/env bash
rank=\${OMPI_COMM_WORLD_RANK:?not started by mpirun}
[ "\$rank" = 0 ] && exec "$dayphoton" "\$@"
export TMPDIR="$tmp/not-a-folder"
mkdir -p "$tmp/cwd-rank\$rank" && cd "$tmp/cwd-rank\$rank" || exit 3
args=()
while [ \$# -gt 0 ]; do
  case "\$1" in
    --output|--cache) args+=("\$1" "\$2-rank\$rank"); shift 2 ;;
    *) args+=("\$1"); shift ;;
  esac
done
exec "$dayphoton" "\${args[@]}"
EOF
  chmod +x "$tmp/rank.sh"
}

# `other_ranks_wrote_nothing FOLDER...`: whether the ranks 1 and 2 that $tmp/rank.sh started
# (other_ranks_wrapper; the test ran 3 ranks) wrote nothing: no "*-rank*" folder of --output or
# --cache beside the FOLDERs those options named, nothing in their working folders, and their
# TMPDIR file unchanged. Prints what it found.
other_ranks_wrote_nothing() {
  local written clean=0
  written=$(find "$@" -maxdepth 1 -name '*-rank*'; find "$tmp"/cwd-rank* -mindepth 1)
  [ -z "$written" ] || { echo "a rank other than 0 wrote files:"; echo "$written" | head; clean=1; }
  [ "$(cat "$tmp/not-a-folder")" = "not a folder" ] || { echo "the other ranks' TMPDIR changed"; clean=1; }
  ls -d "$tmp"/cwd-rank1 "$tmp"/cwd-rank2 > /dev/null || { echo "the wrapper did not start ranks 1 and 2"; clean=1; }
  return $clean
}
