#!/usr/bin/env bash
# Issue 14: `tissue-sim simulate` killed with SIGKILL at random moments leaves the earlier outputs
# intact. Every file is written atomically (tissue/core/atomic_file.h: a temporary in the same
# folder, then rename), so after each kill frames.csv and summary.json are either absent (a fresh
# folder) or complete: every line of the CSV has all columns, one line per frame, and the summary
# is whole JSON. Kills are spread over the run's measured duration, writes included.
set -u
sim="$1"; data="$2"; dir="$3"; rm -rf "$dir"; mkdir -p "$dir"
status=0
fail() { echo "FAIL $*"; status=1; }
frames=200
sed -e "s|\"../meshes/liver.obj\"|\"$data/meshes/liver.obj\"|" -e "s|\"frames\": 1000|\"frames\": $frames|" \
  "$data/scenarios/liver_poke_grasp.json" >"$dir/scenario.json"

# Complete: the CSV has a header and one line per frame, each with the header's column count; the
# summary is whole JSON with the frame count.
complete() {  # folder
  local csv="$1/frames.csv" json="$1/summary.json"
  if [ -e "$csv" ]; then
    [ "$(wc -l <"$csv")" -eq $((frames + 1)) ] || { echo "frames.csv has $(wc -l <"$csv") lines"; return 1; }
    awk -F, 'NR == 1 { n = NF } NF != n { exit 1 }' "$csv" || { echo "frames.csv has a short line"; return 1; }
  fi
  if [ -e "$json" ]; then
    if command -v python3 >/dev/null; then
      python3 -c "import json, sys; d = json.load(open(sys.argv[1])); assert d['frames'] == $frames" "$json" ||
        { echo "summary.json is not whole"; return 1; }
    else
      [ "$(tail -n 1 "$json")" = "}" ] && grep -q "\"frames\": $frames" "$json" || { echo "summary.json is cut"; return 1; }
    fi
  fi
}

start=$(date +%s%N)
"$sim" simulate "$dir/scenario.json" --out "$dir/kept" >/dev/null || fail "the first run failed: exit $?"
run_ms=$((($(date +%s%N) - start) / 1000000))
complete "$dir/kept" || fail "the uninterrupted run's outputs"
[ -s "$dir/kept/frames.csv" ] && [ -s "$dir/kept/summary.json" ] || fail "the uninterrupted run wrote no outputs"
echo "an uninterrupted run: $run_ms ms"

RANDOM=14  # a fixed seed: the same kill times every run
for i in 1 2 3 4 5 6; do
  # Into the folder of a complete earlier run, and into a fresh one.
  for target in kept "fresh$i"; do
    delay_ms=$((RANDOM % (run_ms * 12 / 10 + 1)))
    "$sim" simulate "$dir/scenario.json" --out "$dir/$target" >/dev/null 2>&1 &
    pid=$!
    sleep "$(printf '%d.%03d' $((delay_ms / 1000)) $((delay_ms % 1000)))"
    kill -KILL "$pid" 2>/dev/null
    wait "$pid" 2>/dev/null
    complete "$dir/$target" || fail "kill $i after $delay_ms ms left $target incomplete"
    if [ "$target" = kept ]; then
      [ -s "$dir/kept/frames.csv" ] && [ -s "$dir/kept/summary.json" ] || fail "kill $i after $delay_ms ms lost the earlier outputs"
    fi
  done
done
[ $status -eq 0 ] && echo "PASS: 12 kills, earlier outputs intact, no partial file"
exit $status
