#!/usr/bin/env bash
# The main job: installs what is missing, builds (Release) and runs the default headless
# scenario, writing images and a report into out/main (or the folder given as $1).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TISSUE_BUILD_DIR:-$root/build}"
out="${1:-$root/out/main}"
bash "$root/scripts/build.sh"
"$build/sim/tissue-sim" demo --out "$out"
# The quick speed-accuracy atlas: every method and setting against the path-traced truth
# (issue 13), its chart in $out/atlas (the full atlas: tissue-sim atlas --out DIR).
"$build/sim/tissue-sim" atlas --quick --out "$out/atlas"
