#!/usr/bin/env bash
# The test command: installs what is missing, builds with warnings as errors, runs every test.
# .ci/run calls exactly this.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TISSUE_BUILD_DIR:-$root/build}"
TISSUE_WERROR=ON bash "$root/scripts/build.sh"
cd "$build"
ctest --output-on-failure -j"$(nproc)" --timeout 900
