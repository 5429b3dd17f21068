#!/usr/bin/env bash
# tissue-viewer under Xvfb: 20 frames of the scripted poke, then a screenshot. The picture must
# show a lit organ (not one colour, a fair share of non-background pixels) and differ where
# the poke dents it from a run without the poke. Then the organ in each subsurface method
# (--method): still an organ, and not the lit picture. Exit 77 (skip) without xvfb-run.
set -u
command -v xvfb-run >/dev/null || { echo "SKIP: xvfb-run not installed"; exit 77; }
viewer="$1"; dir="$2"; mkdir -p "$dir"
check="$(dirname "${BASH_SOURCE[0]}")/png_check.py"
rm -f "$dir"/*.png
run() {  # run OUT.PNG [extra options]
  local png="$1"; shift
  xvfb-run -a "$viewer" --width 640 --height 400 --screenshot "$png" "$@" >"$png.log" 2>&1 \
    || { echo "FAIL: tissue-viewer exited $?:"; cat "$png.log"; exit 1; }
  cat "$png.log"
}
run "$dir/poked.png" --frames 20 --poke-script
run "$dir/rest.png" --frames 2
grep -q "scripted poke hits triangle" "$dir/poked.png.log" || { echo "FAIL: the scripted poke missed"; exit 1; }
python3 "$check" organ "$dir/poked.png" && python3 "$check" organ "$dir/rest.png" &&
  python3 "$check" differ "$dir/poked.png" "$dir/rest.png" || exit 1
# Separable SSS and texture-space diffusion blur the lit detail; parallax adds the vessel layer
# (dark red lines under the capsule: at 640 x 400 a few hundred pixels, by 8-27 levels).
for check_of in "separable softer" "texture-space softer" "parallax differ 8 300"; do
  set -- $check_of
  name="$1"; shift
  run "$dir/$name.png" --frames 2 --method "$name"
  python3 "$check" organ "$dir/$name.png" && python3 "$check" "$1" "$dir/$name.png" "$dir/rest.png" "${@:2}" ||
    { echo "FAIL: --method $name"; exit 1; }
done
