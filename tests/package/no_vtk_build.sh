#!/usr/bin/env bash
# The build without VTK and without the viewer, warnings as errors, and its ctest: a second build
# tree (default build-novtk/ beside build/, or $TISSUE_NOVTK_BUILD_DIR). Run by
# scripts/run-tests.sh after the main ctest; not a ctest test itself (it builds the project).
#   tests/package/no_vtk_build.sh [extra cmake options]
# With -DTISSUE_SANITIZE=address,undefined (scripts/run-tests.sh passes it, with clang and
# -DTISSUE_FUZZ=ON) the tree is also the sanitized one (ASan, LSan, UBSan;
# cmake/TissueSanitizers.cmake) and runs the fuzz targets' short passes (label "fuzz"): any finding
# fails its test, and the package test (it builds an unsanitized consumer) runs in the main tree only.
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
exclude='slow|style'
sanitize="$(sed -n 's/^TISSUE_SANITIZE:STRING=//p' "$build/CMakeCache.txt")"
if [ -n "$sanitize" ]; then
  exclude='slow|style|package'
  export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1"
  export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
  export LSAN_OPTIONS="suppressions=$root/tests/sanitizers/lsan.supp:print_suppressions=0"
fi
status=0
ctest --test-dir "$build" --output-on-failure -j"$jobs" --timeout 900 -LE "$exclude" || status=$?
echo "no-VTK build${sanitize:+ (sanitizers: $sanitize)}: configure+build $((built - start)) s, ctest $(($(date +%s) - built)) s"
exit "$status"
