#!/usr/bin/env bash
# Several projects of one command as units under mpirun (study/case_units.h, docs/cluster.md
# "Projects as units"): `dayphoton run office/project.yaml office_variants/project.yaml`
# (the office at a fortieth of its photons, the two-variant office at a quarter: 1 + 3 cases)
# by one process and under `mpirun -np 1`, `-np 2` and `-np 3 --oversubscribe`. Each project
# writes to --output/<its folder's name> with its own cache beside it; every file of both
# results folders and both caches must be byte-identical to the one-process run's (apart from
# run.log, timings.json and the output folder's name in summary.json), and from 2 ranks on
# each project's run.log names the units. The ranks other than 0 write nothing: each gets
# --output of its own (so a cache of its own: the artefacts it computes must reach rank 0 as
# messages), a TMPDIR that is a file and a working folder of its own, none of which may gain
# a file. Then an input error of the second project (its time zone is not its weather
# file's) is reported once, located, under `mpirun -np 2`, and nothing is written.
# Usage: run_projects_under_mpirun.sh DAYPHOTON MPIEXEC SOURCE_DIR
set -uo pipefail
dayphoton=$1
mpiexec=$2
source_dir=$3
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl=self,vader
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0

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

mkdir -p "$tmp/p/office" "$tmp/p/office_variants" "$tmp/p/bad"
cp "$source_dir/projects/office/project.yaml" "$source_dir/projects/office/"*.epw "$tmp/p/office/"
sed -i 's/^  photons_per_bin: 40000$/  photons_per_bin: 1000/; s/^  matrix_format: ascii$/  matrix_format: float/; s/^  images: true$/  images: false/; s/^  report: true$/  report: false/' \
  "$tmp/p/office/project.yaml"
grep -q '^  photons_per_bin: 1000$' "$tmp/p/office/project.yaml" && grep -q '^  report: false$' "$tmp/p/office/project.yaml" ||
  { echo "office: photons_per_bin or report not found"; exit 1; }
cp "$source_dir/projects/office_variants/project.yaml" "$tmp/p/office_variants/"
sed -i 's/^  photons_per_bin: 2000$/  photons_per_bin: 500/; s/^  matrix_format: ascii$/  matrix_format: float\n  images: false\n  report: false/' \
  "$tmp/p/office_variants/project.yaml"
grep -q '^  photons_per_bin: 500$' "$tmp/p/office_variants/project.yaml" &&
  grep -q '^  images: false$' "$tmp/p/office_variants/project.yaml" ||
  { echo "office_variants: photons_per_bin or matrix_format not found"; exit 1; }
# Its weather file is ../office/'s, copied above.
projects=("$tmp/p/office/project.yaml" "$tmp/p/office_variants/project.yaml")

"$dayphoton" run "${projects[@]}" --output "$tmp/out/serial" --quiet > /dev/null ||
  { echo "the one-process run failed"; exit 1; }
for p in office office_variants; do
  [ -f "$tmp/out/serial/$p/summary.json" ] && [ -d "$tmp/out/serial/.$p-cache" ] ||
    { echo "the one-process run wrote no $p/summary.json or .$p-cache"; fail=1; }
done
for np in 1 2 3; do
  out=$tmp/out/np$np
  timeout 300 "$mpiexec" -np $np --oversubscribe --bind-to none "$tmp/rank.sh" run "${projects[@]}" --output "$out" \
    --quiet > "$tmp/np$np.log" 2>&1
  rc=$?
  [ $rc -eq 0 ] || { echo "mpirun -np $np: exit $rc"; cat "$tmp/np$np.log"; fail=1; continue; }
  # Both results folders and both caches (.office-cache, .office_variants-cache).
  if ! diff -r -q -x run.log -x timings.json -x summary.json "$tmp/out/serial" "$out"; then
    echo "mpirun -np $np wrote other results or cached other artefacts than the one-process run"
    fail=1
  fi
  for p in office office_variants; do
    if ! cmp -s <(sed "s|$tmp/out/serial|OUT|g" "$tmp/out/serial/$p/summary.json") \
                <(sed "s|$out|OUT|g" "$out/$p/summary.json"); then
      echo "$p: mpirun -np $np wrote another summary.json than the one-process run"
      fail=1
    fi
    # Four cases in all: units from 2 ranks on, named in each project's run.log.
    units=$(grep -c "^cases of 2 projects as units over $np ranks: rank 0 project" "$out/$p/run.log")
    if [ $np -ge 2 ]; then expected=1; else expected=0; fi
    [ "$units" -eq $expected ] || { echo "$p: mpirun -np $np: $units line(s) on units, not $expected"; fail=1; }
    # The project's own units are not made again.
    grep -q "^cases as units" "$out/$p/run.log" && { echo "$p: mpirun -np $np: the project's cases as units again"; fail=1; }
  done
done
written=$(find "$tmp/out" -maxdepth 1 -name '*-rank*'; find "$tmp"/cwd-rank* -mindepth 1)
[ -z "$written" ] || { echo "a rank other than 0 wrote files:"; echo "$written" | head; fail=1; }
[ "$(cat "$tmp/not-a-folder")" = "not a folder" ] || { echo "the other ranks' TMPDIR changed"; fail=1; }
ls -d "$tmp"/cwd-rank1 "$tmp"/cwd-rank2 > /dev/null || { echo "the wrapper did not start ranks 1 and 2"; fail=1; }

# An input error of the second project: its site on another clock than its weather file.
cp "$tmp/p/office/project.yaml" "$tmp/p/office/"*.epw "$tmp/p/bad/"
sed -i 's/^  time_zone: -8 /  time_zone: -5 /' "$tmp/p/bad/project.yaml"
line=$(grep -n '^  time_zone: -5 ' "$tmp/p/bad/project.yaml" | cut -d: -f1)
[ -n "$line" ] || { echo "bad: time_zone not found"; exit 1; }
timeout 120 "$mpiexec" -np 2 --oversubscribe --bind-to none "$tmp/rank.sh" run "$tmp/p/office/project.yaml" \
  "$tmp/p/bad/project.yaml" --output "$tmp/out/bad" > "$tmp/bad.out" 2> "$tmp/bad.err"
rc=$?
[ $rc -eq 1 ] || { echo "input error of the second project: exit $rc, not 1"; cat "$tmp/bad.err"; fail=1; }
located=$(grep -c "bad/project.yaml:$line:" "$tmp/bad.err")
[ "$located" -eq 1 ] || { echo "input error printed $located times located at line $line, not once:"; cat "$tmp/bad.err"; fail=1; }
grep -q "MPI_Abort\|MPI_ABORT" "$tmp/bad.err" && { echo "input error ended by MPI_Abort"; fail=1; }
[ ! -e "$tmp/out/bad" ] || { echo "input error of the second project, but something was written:"; find "$tmp/out/bad" | head; fail=1; }
exit $fail
