#!/usr/bin/env bash
# The test command: installs what is missing, builds with warnings as errors, runs every test,
# then builds and tests a second tree without VTK and the viewer, sanitized: clang with ASan, LSan
# and UBSan over every target, and libFuzzer's targets with a short pass each (label "fuzz")
# (tests/package/no_vtk_build.sh -DTISSUE_SANITIZE=address,undefined -DTISSUE_FUZZ=ON,
# <build>-san; any finding fails its test), then the short pass of the two VTK-backed loaders in a
# small tree of their own (tests/fuzz/vtk_fuzz_pass.sh, <build>-fuzz-vtk).
# TISSUE_SANITIZED_BUILD=0 makes the second tree the plain no-VTK one (<build>-novtk, quicker, no
# fuzzing), TISSUE_NOVTK_BUILD=0 skips it.
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
      bash "$root/tests/package/no_vtk_build.sh" -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
      -DTISSUE_SANITIZE=address,undefined -DTISSUE_FUZZ=ON || status=$?
    bash "$root/tests/fuzz/vtk_fuzz_pass.sh" "$build-fuzz-vtk" || status=$?
  else
    TISSUE_NOVTK_BUILD_DIR="${TISSUE_NOVTK_BUILD_DIR:-$build-novtk}" bash "$root/tests/package/no_vtk_build.sh" || status=$?
  fi
fi
exit "$status"
