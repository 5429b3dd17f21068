#!/usr/bin/env bash
# The test command: installs what is missing, builds with warnings as errors, runs every test,
# then builds and tests a second tree without VTK and the viewer, sanitized: ASan, LSan and UBSan
# over every target (tests/package/no_vtk_build.sh -DTISSUE_SANITIZE=address,undefined,
# <build>-san; any finding fails its test). TISSUE_SANITIZED_BUILD=0 makes that second tree the
# plain no-VTK one (<build>-novtk, quicker), TISSUE_NOVTK_BUILD=0 skips it.
# .ci/run calls exactly this.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TISSUE_BUILD_DIR:-$root/build}"
TISSUE_WERROR=ON bash "$root/scripts/build.sh"
status=0
(cd "$build" && ctest --output-on-failure -j"$(nproc)" --timeout 900) || status=$?
if [ "${TISSUE_NOVTK_BUILD:-1}" != 0 ]; then
  if [ "${TISSUE_SANITIZED_BUILD:-1}" != 0 ]; then
    TISSUE_NOVTK_BUILD_DIR="${TISSUE_NOVTK_BUILD_DIR:-$build-san}" \
      bash "$root/tests/package/no_vtk_build.sh" -DTISSUE_SANITIZE=address,undefined || status=$?
  else
    TISSUE_NOVTK_BUILD_DIR="${TISSUE_NOVTK_BUILD_DIR:-$build-novtk}" bash "$root/tests/package/no_vtk_build.sh" || status=$?
  fi
fi
exit "$status"
