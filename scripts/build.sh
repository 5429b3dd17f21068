#!/usr/bin/env bash
# Configures and builds tissue (Release) into build/ (or $TISSUE_BUILD_DIR).
# Installs missing Debian packages first (needs root; a no-op when all are present).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TISSUE_BUILD_DIR:-$root/build}"
bash "$root/scripts/install-deps.sh"
werror=OFF
if [ "${CI:-}" = "true" ] || [ "${TISSUE_WERROR:-}" = "ON" ]; then werror=ON; fi
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DTISSUE_WERROR=$werror "$@"
cmake --build "$build" -j"$(nproc)"
