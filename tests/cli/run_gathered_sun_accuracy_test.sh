#!/bin/bash
# The accuracy target on a grid estimated by final gather in the sun bins' rounds
# (docs/photon-tracing.md "Accuracy target", "Gathered grids in the sun bins' rounds"):
# tests/cli/cases/gathered_sun_accuracy.yaml has one grid on the back wall (18 sensors off every
# receiver plane), sun bins, the draft target (5 %) and 16 gather rays per sensor, far too few
# for the annual sun-bin illuminance (about 40 % after the sun's pilot). The sun rounds must
# give it gather rounds until it meets the target, and say so:
#   - summary.json grids[0].accuracy.sun: status "met", stop_reason "target met", reached <= 5 %,
#     gather {first_gather_rays 16, gather_rays > 16 (a square), rounds >= 1, stop_reason
#     "target met"}; results.json's sun_accuracy.gather the same rays, rounds and stop;
#   - run.log has a line per sun gather round and the grid's sentence;
#   - 1 and 2 threads give the same result bytes (run.log and timings.json aside).
# Usage: DAYPHOTON=path/to/dayphoton bash run_gathered_sun_accuracy_test.sh (from the source root)
case_file=tests/cli/cases/gathered_sun_accuracy.yaml
. "$(dirname "$0")/thread_runs.sh"
python3 - "$scratch/1" <<'PY' || failed=1
import json, math, sys
out = sys.argv[1]
grid = json.load(open(out + "/summary.json"))["grids"][0]
s = grid["accuracy"]["sun"]
g = s["gather"]
print("back_wall sun:", json.dumps(s))
assert grid["name"] == "back_wall", grid["name"]
assert s["status"] == "met" and s["stop_reason"] == "target met", s
assert s["reached_relative_stderr_percent"] <= s["target_relative_stderr_percent"] == 5.0, s
assert g["first_gather_rays"] == 16 and g["gather_rays"] > 16 and g["rounds"] >= 1, g
assert g["stop_reason"] == "target met", g
k = int(round(math.sqrt(g["gather_rays"])))
assert k * k == g["gather_rays"], g
r = json.load(open(out + "/results.json"))["cases"][0]["grids"][0]["sun_accuracy"]
assert r["gather"] == {"rays": g["gather_rays"], "rounds": g["rounds"], "stop_reason": g["stop_reason"]}, r
assert r["reached_percent"] == s["reached_relative_stderr_percent"] and r["status"] == "met", r
log = open(out + "/run.log").read()
assert "sun accuracy gather round 1, grid back_wall: " in log, log
assert "(final gather, %d rays per sensor, %d gather round(s) from 16: target met)" % (g["gather_rays"], g["rounds"]) in log, log
print("ok   gathered grid met the sun target: %.3g %% with %d rays per sensor after %d gather round(s)"
      % (s["reached_relative_stderr_percent"], g["gather_rays"], g["rounds"]))
PY
check_same_bytes
exit $failed
