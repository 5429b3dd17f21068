#!/usr/bin/env bash
# Configures and builds tissue (Release) into build/ (or $TISSUE_BUILD_DIR).
# Installs missing Debian packages first (needs root; a no-op when all are present).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TISSUE_BUILD_DIR:-$root/build}"
bash "$root/scripts/install-deps.sh"
# Warnings are errors in every build (the same flags for the main job and the tests, so switching
# between the two commands never rebuilds everything); TISSUE_WERROR=OFF relaxes it locally.
werror="${TISSUE_WERROR:-ON}"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DTISSUE_WERROR="$werror" "$@"
cmake --build "$build" -j"$(nproc)"
