#!/usr/bin/env bash
# The build without VTK and without the viewer, warnings as errors, and its ctest: a second build
# tree (default build-novtk/ beside build/, or $TISSUE_NOVTK_BUILD_DIR). Run by
# scripts/run-tests.sh after the main ctest; not a ctest test itself (it builds the project).
#   tests/package/no_vtk_build.sh [extra cmake options]
# ccache is used when present. The "slow" (minutes, VTK-independent) and "style" (the same files
# as the main tree) tests run in the main tree only.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${TISSUE_NOVTK_BUILD_DIR:-$root/build-novtk}"
jobs="$(nproc)"
launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
start=$(date +%s)
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DTISSUE_WITH_VTK=OFF -DTISSUE_BUILD_VIEWER=OFF \
  -DTISSUE_BUILD_BENCHMARKS=OFF -DTISSUE_WERROR=ON "${launcher[@]}" "$@"
cmake --build "$build" -j"$jobs"
built=$(date +%s)
# Nothing of this tree links VTK (a build option, not a silent fallback).
if grep -rlis --include=link.txt 'libvtk\|vtk-9' "$build"; then
  echo "FAIL: targets of the no-VTK build link VTK (above)"
  exit 1
fi
status=0
ctest --test-dir "$build" --output-on-failure -j"$jobs" --timeout 900 -LE 'slow|style' || status=$?
echo "no-VTK build: configure+build $((built - start)) s, ctest $(($(date +%s) - built)) s"
exit "$status"
