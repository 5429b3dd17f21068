#!/usr/bin/env bash
# The test command: installs what is missing, builds with warnings as errors, runs every test,
# then builds and tests the configuration without VTK and the viewer in a second tree
# (tests/package/no_vtk_build.sh, <build>-novtk; TISSUE_NOVTK_BUILD=0 skips it).
# .ci/run calls exactly this.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TISSUE_BUILD_DIR:-$root/build}"
TISSUE_WERROR=ON bash "$root/scripts/build.sh"
status=0
(cd "$build" && ctest --output-on-failure -j"$(nproc)" --timeout 900) || status=$?
if [ "${TISSUE_NOVTK_BUILD:-1}" != 0 ]; then
  TISSUE_NOVTK_BUILD_DIR="${TISSUE_NOVTK_BUILD_DIR:-$build-novtk}" bash "$root/tests/package/no_vtk_build.sh" || status=$?
fi
exit "$status"
