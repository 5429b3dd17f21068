#!/usr/bin/env bash
# tissue-sim inspect end to end: the default scenario and the shipped session each write every
# view (PNG and .vtp) of a frame; simulate --pvd writes a 12-frame ParaView series; bad input (a
# frame past the end, a session of another mesh, a missing file) is one line on stderr with the
# fix, and a non-zero exit.
#   inspect_cli_test.sh TISSUE_SIM DATA_DIR OUT_DIR
set -u
sim="$1"; data="$2"; dir="$3"; rm -rf "$dir"; mkdir -p "$dir"
status=0
fail() { echo "FAIL $*"; status=1; }
views="spring_strain vertex_stretch contact_force plane_fit tangent_frames texture_stretch"

"$sim" --json inspect "$data/scenarios/liver_poke_grasp.json" --frame 190 --out "$dir/scenario" --width 480 --height 360 \
  >"$dir/scenario.json" || fail "inspect SCENARIO exit $?"
"$sim" inspect "$data/sessions/liver_poke_grasp.json" --frame 30 --out "$dir/session" --width 480 --height 360 \
  >/dev/null || fail "inspect SESSION exit $?"
for run in scenario session; do
  for v in $views; do
    [ -s "$dir/$run/$v.png" ] || fail "$run: no $v.png"
    [ -s "$dir/$run/$v.vtp" ] || fail "$run: no $v.vtp"
  done
done
grep -q '"frame": 190' "$dir/scenario.json" || fail "inspect --json lacks the frame"

# --truth-error: the separable method's error against a short truth, mapped onto the mesh.
"$sim" --json inspect "$data/scenarios/liver_poke_grasp.json" --frame 60 --out "$dir/truth" --width 480 \
  --height 360 --truth-error separable --truth-seconds 2 >"$dir/truth.json" || fail "inspect --truth-error exit $?"
[ -s "$dir/truth/truth_error.png" ] && [ -s "$dir/truth/truth_error.vtp" ] || fail "no truth_error view"
grep -q '"noise_rel_rms"' "$dir/truth.json" || fail "inspect --truth-error reports no truth noise"
grep -q '"visible_vertices": [1-9]' "$dir/truth.json" || fail "no vertex sees the truth error"

# simulate --pvd: the ParaView series of every frame (one .vtp each, listed in the .pvd).
"$sim" simulate "$data/scenarios/liver_poke_grasp.json" --frames 12 --out "$dir/simulate" --pvd "$dir/pvd" \
  >/dev/null || fail "simulate --pvd exit $?"
pvd=$(ls "$dir"/pvd/*.pvd 2>/dev/null | head -1)
[ -n "$pvd" ] || fail "simulate --pvd wrote no .pvd"
[ "$(grep -c '<DataSet ' "$pvd")" -eq 12 ] || fail "the .pvd lists $(grep -c '<DataSet ' "$pvd") frames, not 12"
[ "$(ls "$dir"/pvd/ | grep -c '\.vt[pu]$')" -eq 12 ] || fail "not 12 frame files beside the .pvd"
grep -q '"pvd"' "$dir/simulate/summary.json" || fail "summary.json does not name the series"

# Bad input. The session of another mesh keeps its scenario reachable (an absolute path).
sed -e 's/"mesh_vertices": [0-9]*/"mesh_vertices": 12/' \
    -e "s|\"scenario\": \"[^\"]*\"|\"scenario\": \"$data/scenarios/liver_poke_grasp.json\"|" \
    "$data/sessions/liver_poke_grasp.json" >"$dir/other.json"
check() {  # check EXPECTED_TEXT ARGS...: one line on stderr containing the text, non-zero exit
  local want="$1"; shift
  "$sim" "$@" >"$dir/out.txt" 2>"$dir/err.txt"; local rc=$?
  if [ "$rc" -eq 0 ] || [ "$(wc -l <"$dir/err.txt")" -ne 1 ] || ! grep -q -- "$want" "$dir/err.txt"; then
    fail "$*: exit $rc"; cat "$dir/err.txt"
  fi
}
check "pass --frame 0..1000" inspect "$data/scenarios/liver_poke_grasp.json" --frame 1001 --out "$dir/x"
check "replay it with the scenario it was recorded with" inspect "$dir/other.json" --frame 1 --out "$dir/x"
check "missing.json" inspect "$dir/missing.json" --out "$dir/x"
check "--truth-error: " inspect "$data/scenarios/liver_poke_grasp.json" --frame 1 --out "$dir/x" --truth-error glossy
[ "$status" -eq 0 ] && echo "ok"
exit "$status"
