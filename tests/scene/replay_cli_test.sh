#!/usr/bin/env bash
# The main job's loop and replay end to end: `demo` renders while it simulates (frame images
# every N frames, the per-phase median and p99) and records a session; two `replay`s of it give
# the same positions_sha256; the shipped session replays; bad input is one line, non-zero exit.
set -u
sim="$1"; dir="$2"; rm -rf "$dir"; mkdir -p "$dir"
status=0
fail() { echo "FAIL $*"; status=1; }

"$sim" --json demo --out "$dir/demo" --frames 200 --image-every 100 --record "$dir/s.json" >"$dir/demo.json" \
  || fail "demo exit $?"
for f in frames/frame_0100.png frames/frame_0200.png frame_sequence.png report.md report.json frames.csv; do
  [ -s "$dir/demo/$f" ] || fail "demo wrote no $f"
done
for key in '"phases_ms"' '"median_ms"' '"p99_ms"' '"4 render (lit, read back)"' '"3 upload"'; do
  grep -q "$key" "$dir/demo.json" || fail "demo --json lacks $key"
done
grep -q '| 4 render (lit, read back) |' "$dir/demo/report.md" || fail "report.md lacks the render phase"
[ -s "$dir/s.json" ] || fail "demo --record wrote no session"

"$sim" --json replay "$dir/s.json" >"$dir/r1.json" || fail "replay 1 exit $?"
"$sim" --json replay "$dir/s.json" --render --out "$dir/replay" --image-every 100 >"$dir/r2.json" || fail "replay 2 exit $?"
h1=$(grep -o '"positions_sha256": *"[0-9a-f]*"' "$dir/r1.json"); h2=$(grep -o '"positions_sha256": *"[0-9a-f]*"' "$dir/r2.json")
[ -n "$h1" ] && [ "$h1" = "$h2" ] || fail "replays differ: $h1 vs $h2"
for key in '"frame_ms"' '"median"' '"p99"' '"max"' '"phases_ms"'; do
  grep -q "$key" "$dir/r1.json" || fail "replay --json lacks $key"
done
[ -s "$dir/replay/frame_0200.png" ] || fail "replay --render --out wrote no frame image"
[ -s "$dir/replay/report.json" ] || fail "replay --out wrote no report.json"

# Bad input: a missing file, a session of another mesh, a NaN pose.
sed 's/"mesh_vertices": [0-9]*/"mesh_vertices": 12/' "$dir/s.json" >"$dir/other.json"
sed '0,/"pose":\[[^]]*\]/s//"pose":[1e400,0,0]/' "$dir/s.json" >"$dir/nan.json"
for args in "replay $dir/missing.json" "replay $dir/other.json" "replay $dir/nan.json" "demo --out $dir/x --image-every 0"; do
  $sim $args >"$dir/out.txt" 2>"$dir/err.txt"; rc=$?
  if [ "$rc" -eq 0 ] || [ "$(wc -l <"$dir/err.txt")" -ne 1 ]; then fail "$args: exit $rc"; cat "$dir/err.txt"; fi
done
grep -q "replay it with the scenario it was recorded with" <("$sim" replay "$dir/other.json" 2>&1) \
  || fail "another mesh: no fix in the message"
[ "$status" -eq 0 ] && echo "ok"
exit $status
