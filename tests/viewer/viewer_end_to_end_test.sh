#!/usr/bin/env bash
# tissue-viewer under Xvfb at 640 x 480: the library's loop (simulate, mesh, upload, render into
# the window) with the ImGui panel on top.
#  1 the scripted poke (the scenario's own instrument path, no input) for 200 frames, recorded:
#    the screenshot shows the organ, the steel-grey instrument and the panel; the log names the
#    simulate phase, and the force is non-zero around the deepest poke (frames 180-200);
#  2 that session replayed (--replay), with layered parallax recorded as the method: the
#    same forces frame by frame (deterministic), the method switched, the same checks;
#  3 the ray-march method for a few frames: an organ, and not the lit picture;
#  4 a session of tissue-sim demo --record replays in the viewer;
#  5 the viewer under a frame budget (--budget-ms) reports the controller's choice.
# Fails (never skips) when no window can be created: xvfb-run is part of the build's dependencies.
set -u
viewer="$1"; sim="$2"; dir="$3"; mkdir -p "$dir"
check="$(dirname "${BASH_SOURCE[0]}")/png_check.py"
rm -f "$dir"/*.png "$dir"/*.csv "$dir"/*.json
command -v xvfb-run >/dev/null || { echo "FAIL: xvfb-run not installed (scripts/install-deps.sh)"; exit 1; }
run() {  # run NAME [options]: NAME.png, NAME.csv (per frame) and NAME.log (stdout and stderr)
  local name="$1"; shift
  xvfb-run -a -s "-screen 0 640x480x24" "$viewer" --width 640 --height 480 --screenshot "$dir/$name.png" \
    --log "$dir/$name.csv" "$@" >"$dir/$name.log" 2>&1 || { echo "FAIL: tissue-viewer $* exited $?:"; cat "$dir/$name.log"; exit 1; }
  tail -n 3 "$dir/$name.log"
}
# The force (N) is above zero in frames 180-200 of NAME.csv, which has ROWS frames.
forces() {  # forces NAME ROWS
  python3 - "$dir/$1.csv" "$2" <<'PY' || exit 1
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
if len(rows) != int(sys.argv[2]): sys.exit(f"FAIL: {len(rows)} frames logged, expected {sys.argv[2]}")
deepest = max(float(r["force_N"]) for r in rows[180:200])
print(f"{sys.argv[1]}: largest force in frames 180-200: {deepest:.4f} N; simulate {rows[-1]['simulate_ms']} ms")
if not deepest > 0: sys.exit("FAIL: no force at the deepest poke")
PY
}
pictures() {  # pictures NAME: organ, instrument right of the panel, panel
  python3 "$check" organ "$dir/$1.png" && python3 "$check" steel "$dir/$1.png" 270 300 &&
    python3 "$check" panel "$dir/$1.png" 1500 || exit 1
}

run poke --frames 200 --poke-script --method parallax --record "$dir/poke_session.json"
grep -q "| simulate [0-9.]* |" "$dir/poke.log" || { echo "FAIL: the per-frame log does not name the simulate phase"; exit 1; }
grep -q "force [0-9.]* N" "$dir/poke.log" || { echo "FAIL: the per-frame log does not give the force"; exit 1; }
grep -q "recorded 200 frames" "$dir/poke.log" || { echo "FAIL: the session was not saved"; exit 1; }
forces poke 200
pictures poke

run replay --replay "$dir/poke_session.json"
forces replay 200
pictures replay
cut -d, -f1,7,9 "$dir/poke.csv" > "$dir/poke_forces.txt"
cut -d, -f1,7,9 "$dir/replay.csv" > "$dir/replay_forces.txt"
python3 - "$dir/poke_forces.txt" "$dir/replay_forces.txt" <<'PY' || exit 1
import sys
a, b = (open(f).read().splitlines()[1:] for f in sys.argv[1:])
worst = max(abs(float(x.split(",")[1]) - float(y.split(",")[1])) for x, y in zip(a, b))
print(f"replay against the recording: largest force difference {worst:.2e} N")
if worst > 1e-3: sys.exit("FAIL: the replay does not reproduce the recorded run")
PY
grep -q "parallax$" "$dir/replay.csv" || { echo "FAIL: the recorded method was not replayed"; exit 1; }

run lit --frames 3
run raymarch --frames 3 --method ray-march
python3 "$check" organ "$dir/raymarch.png" && python3 "$check" differ "$dir/raymarch.png" "$dir/lit.png" || exit 1

# 5 under a frame budget: the controller's choice is drawn and reported (its options' settings are
#   built on the catalog's worker meanwhile; lit's from the first frame).
run budget --frames 40 --poke-script --budget-ms 5000
grep -Eq "^tissue-viewer: (lit|separable|texture-space|ray-march|parallax) [a-z0-9-]+ \|.*\| budget 5000.0 ms \([0-9]+ options pending\)" "$dir/budget.log" ||
  { echo "FAIL: the viewer under --budget-ms does not report the controller's choice"; cat "$dir/budget.log"; exit 1; }
# the per-frame log names the drawn option (method and setting) under the budget
tail -n 1 "$dir/budget.csv" | grep -Eq ",(lit|separable|texture-space|ray-march|parallax) [a-z0-9-]+$" ||
  { echo "FAIL: the per-frame log under --budget-ms does not name the drawn option"; tail -n 2 "$dir/budget.csv"; exit 1; }
python3 "$check" organ "$dir/budget.png" || exit 1

"$sim" demo --out "$dir/demo" --frames 30 --width 64 --height 48 --loop-width 64 --loop-height 48 --record "$dir/demo_session.json" >"$dir/demo.log" 2>&1 ||
  { echo "FAIL: tissue-sim demo --record:"; tail -5 "$dir/demo.log"; exit 1; }
run demo_replay --replay "$dir/demo_session.json"
grep -q "30 frames" "$dir/demo_replay.log" || { echo "FAIL: the demo's session did not replay"; exit 1; }
echo "ok"
