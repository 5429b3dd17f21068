#!/usr/bin/env bash
# The short fuzz pass of the two VTK-backed loaders (.vtk legacy, .vtu XML): the sanitized test
# tree is built without VTK, so these two targets get a small tree of their own, clang with ASan,
# UBSan and libFuzzer, that builds only them and what they link (tissue::volume with VTK,
# tissue::core). Run by scripts/run-tests.sh after the sanitized tree, whose ctest runs the other
# targets' passes (label "fuzz"); docs/DECISIONS.md, "The fuzz pass in the test command".
#   tests/fuzz/vtk_fuzz_pass.sh [BUILD_DIR]   (default build-fuzz-vtk/ beside build/)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${1:-$root/build-fuzz-vtk}"
launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
start=$(date +%s)
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DTISSUE_SANITIZE=address,undefined -DTISSUE_FUZZ=ON -DTISSUE_BUILD_VIEWER=OFF -DTISSUE_BUILD_BENCHMARKS=OFF \
  -DTISSUE_WERROR=ON "${launcher[@]}" >/dev/null
cmake --build "$build" -j"$(nproc)" --target tissue_fuzz_vtk tissue_fuzz_vtu
built=$(date +%s)
export ASAN_OPTIONS="abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
status=0
ctest --test-dir "$build" --output-on-failure -j"$(nproc)" -R '^tissue_fuzz_(vtk|vtu)$' || status=$?
echo "VTK fuzz pass: configure+build $((built - start)) s, fuzzing $(($(date +%s) - built)) s"
exit "$status"
