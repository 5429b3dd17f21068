#!/usr/bin/env bash
# tissue-sim stability and sim-bench from the command line: the JSON keys the issue specifies,
# the files of `stability --out`, and bad options as one line on stderr with a non-zero exit.
set -u
sim="$1"; dir="$2"; rm -rf "$dir"; mkdir -p "$dir"
status=0
fail() { echo "FAIL $*"; status=1; }

"$sim" stability --json --masses 1 --stiffnesses 0.1 >"$dir/stability.json" || fail "stability --json exit $?"
for key in '"cases"' '"theory_max_dt"' '"measured_max_dt": null' '"integrator": "fast-mass-spring"' \
           '"integrator": "implicit-euler"' '"integrator": "symplectic-euler"'; do
  grep -q "$key" "$dir/stability.json" || fail "stability --json lacks $key"
done

"$sim" stability --masses 1 --stiffnesses 0.1 0.2 --out "$dir/study" >/dev/null 2>"$dir/err.txt"
for f in stability.md stability.json stability_chart.csv; do
  [ -s "$dir/study/$f" ] || fail "stability --out wrote no $f"
done
grep -q "fast-mass-spring" "$dir/study/stability.md" || fail "stability.md lacks the fast solver"
# The chart needs an X display or Xvfb; without one the command must say so in one line.
[ -s "$dir/study/stability.png" ] || [ "$(wc -l <"$dir/err.txt")" -eq 1 ] || fail "no chart and no one-line error"

"$sim" sim-bench --json --max-springs 1000 --skip-frame-path >"$dir/bench.json" || fail "sim-bench exit $?"
for key in '"results"' '"ms_per_step"' '"springs_per_second"' '"force_pass"' '"integrator": "fast-mass-spring"' \
           '"integrator": "verlet"'; do
  grep -q "$key" "$dir/bench.json" || fail "sim-bench --json lacks $key"
done

for args in "sim-bench --threads 0" "sim-bench --max-springs 10" "stability --masses -1"; do
  $sim $args >"$dir/out.txt" 2>"$dir/err.txt"; rc=$?
  if [ "$rc" -eq 0 ] || [ "$(wc -l <"$dir/err.txt")" -ne 1 ]; then fail "$args: exit $rc"; cat "$dir/err.txt"; fi
done
[ "$status" -eq 0 ] && echo "ok"
exit $status
