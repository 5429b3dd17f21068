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
# ccache (installed by install-deps.sh) lets the test command's further trees reuse these objects.
launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DTISSUE_WERROR="$werror" "${launcher[@]}" "$@"
cmake --build "$build" -j"$(nproc)"
