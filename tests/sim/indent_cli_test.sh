#!/usr/bin/env bash
# tissue-sim indent from the command line: the JSON keys the issue specifies (a small block, so it
# runs in about a second), and bad options as one line on stderr with a non-zero exit.
set -u
sim="$1"; dir="$2"; rm -rf "$dir"; mkdir -p "$dir"
status=0
fail() { echo "FAIL $*"; status=1; }

"$sim" indent --json --cells 8 --cells-per-radius 3 --radius-mm 6 >"$dir/indent.json" || fail "indent --json exit $?"
for key in '"youngs_modulus_kpa"' '"poisson_ratio": 0.25' '"configured_poisson_ratio"' '"sphere_radius_mm": 6' \
           '"uniaxial_modulus_ratio"' '"uniaxial_modulus_ratio_lattice"' '"uniaxial_modulus_ratio_tets"' \
           '"results"' '"depth_mm"' '"force_N"' '"hertz_N"' '"network": "tets"'; do
  grep -q "$key" "$dir/indent.json" || fail "indent --json lacks $key"
done

# A Poisson's ratio the springs cannot realise: accepted, one warning line.
"$sim" indent --json --network lattice --cells 6 --cells-per-radius 2 --poisson-ratio 0.45 \
  >"$dir/nu.json" 2>"$dir/nu_err.txt" || fail "indent --poisson-ratio 0.45 exit $?"
grep -q '"configured_poisson_ratio": 0.45' "$dir/nu.json" || fail "configured_poisson_ratio not reported"
[ "$(wc -l <"$dir/nu_err.txt")" -eq 1 ] || fail "--poisson-ratio 0.45: expected one warning line"

for args in "indent --youngs-modulus-kpa -3" "indent --poisson-ratio 0.5" "indent --radius-mm 0" \
            "indent --network springs" "indent --cells 2" "indent --tet-formula foo"; do
  $sim $args >"$dir/out.txt" 2>"$dir/err.txt"; rc=$?
  if [ "$rc" -eq 0 ] || [ "$(wc -l <"$dir/err.txt")" -ne 1 ]; then fail "$args: exit $rc"; cat "$dir/err.txt"; fi
done
[ "$status" -eq 0 ] && echo "ok"
exit $status
