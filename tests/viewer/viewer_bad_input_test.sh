#!/usr/bin/env bash
# tissue-viewer on bad input: exactly one line on stderr naming the file or option, exit code
# 1 or 2, no core dump. All fail before a window is needed (no display).
set -u
viewer="$1"; dir="$2"; mkdir -p "$dir"
scenario="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../data/scenarios" && pwd)/liver_poke_grasp.json"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' > "$dir/no_uvs.obj"
# A scenario whose mesh has no UVs: the scene module gives it the automatic atlas, but the one
# open triangle cannot hold the scenario's lattice springs (the error names the scenario).
sed -e "s#\"../meshes/liver.obj\"#\"$dir/no_uvs.obj\"#" -e 's#"below": -13#"below": -1#' "$scenario" > "$dir/no_uvs_scenario.json"
# Sessions: one recorded on another mesh (3 vertices), one with a non-finite pose, one NaN.
session() {  # session FILE VERTICES POSE
  printf '{"format": "tissue-session", "version": 1, "scenario": "%s", "frame_time_s": 0.016666666666666666,
  "mesh_vertices": %s, "mesh_rest_sha256": "0000", "frames": [{"pose": [31.82, 0, 75], "grasp": false},
  {"pose": %s, "grasp": false}]}\n' "$scenario" "$2" "$3" > "$1"
}
session "$dir/other_mesh.json" 3 "[31.82, 0, 74]"
session "$dir/infinite_pose.json" 3 "[31.82, 1e999, 74]"
session "$dir/nan_pose.json" 3 "[NaN, 0, 74]"
status=0
check() {  # check NAME EXPECTED-TEXT COMMAND...
  local name="$1" expect="$2"; shift 2
  "$@" >"$dir/out.txt" 2>"$dir/err.txt"; local rc=$?
  local lines; lines=$(wc -l <"$dir/err.txt")
  if [ "$rc" -ne 1 ] && [ "$rc" -ne 2 ] || [ "$lines" -ne 1 ] || ! grep -q -- "$expect" "$dir/err.txt"; then
    echo "FAIL $name: exit $rc, $lines stderr lines:"; cat "$dir/err.txt"; status=1
  else
    echo "ok $name: $(cat "$dir/err.txt")"
  fi
}
check no-display "run under a display or xvfb-run" env -u DISPLAY -u WAYLAND_DISPLAY "$viewer" --frames 1
check missing-scenario "missing.json" env -u DISPLAY "$viewer" --scenario "$dir/missing.json" --frames 1
check no-uvs-open-mesh "no_uvs_scenario.json: springs.from" env -u DISPLAY "$viewer" --scenario "$dir/no_uvs_scenario.json" --frames 1
check other-mesh "other_mesh.json" env -u DISPLAY "$viewer" --replay "$dir/other_mesh.json"
check infinite-pose "infinite_pose.json" env -u DISPLAY "$viewer" --replay "$dir/infinite_pose.json"
check nan-pose "nan_pose.json" env -u DISPLAY "$viewer" --replay "$dir/nan_pose.json"
check missing-session "missing_session.json" env -u DISPLAY "$viewer" --replay "$dir/missing_session.json"
check bad-option "--frames" "$viewer" --frames -3
check bad-method "--method" "$viewer" --method bogus --frames 1
exit $status
