#!/usr/bin/env bash
# The long fuzz campaigns (issue 14): every libFuzzer target for RUNS executions (default 1M)
# under ASan + UBSan + LSan, JOBS targets at a time, each through tests/fuzz/run_fuzzer.sh (the
# same bounds as the test suite's short pass). A summary table goes to OUT/summary.md, the
# working corpora and each target's whole log under OUT.
#   scripts/fuzz.sh [--tree DIR] [--vtk-tree DIR] [--runs N] [--jobs J] [--out DIR] [TARGET ...]
# The trees are the test command's: <build>-san (clang, sanitized, the fuzz targets without VTK)
# and <build>-fuzz-vtk (the .vtk and .vtu targets); build them first (scripts/run-tests.sh does,
# or tests/fuzz/vtk_fuzz_pass.sh for the second).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
tree="$root/build-san" vtk_tree="$root/build-fuzz-vtk" runs=1000000 jobs=1 out="$root/out/fuzz"
targets=()
while [ $# -gt 0 ]; do
  case "$1" in
    --tree) tree="$2"; shift 2 ;;
    --vtk-tree) vtk_tree="$2"; shift 2 ;;
    --runs) runs="$2"; shift 2 ;;
    --jobs) jobs="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    -*) echo "fuzz.sh: unknown option '$1'; see the usage at the top of scripts/fuzz.sh" >&2; exit 2 ;;
    *) targets+=("$1"); shift ;;
  esac
done
[ ${#targets[@]} -gt 0 ] || targets=(obj ply off stl msh vtk vtu scenario material medium session png)
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$root/tests/sanitizers/lsan.supp:print_suppressions=0"
mkdir -p "$out"
one() {
  local t="$1" dir="$tree"
  case "$t" in vtk | vtu) dir="$vtk_tree" ;; esac
  local exe="$dir/tests/fuzz/tissue_fuzz_$t"
  if [ ! -x "$exe" ]; then
    echo "| $t | - | - | - | not built: $exe is missing; build the tree first |" >"$out/$t.row"
    return 1
  fi
  local start status=0
  start=$(date +%s)
  bash "$root/tests/fuzz/run_fuzzer.sh" "$exe" "$root/tests/fuzz/corpus/$t" "$out/work/$t" 86400 "$runs" \
    >"$out/$t.out" 2>&1 || status=$?
  local secs=$(($(date +%s) - start)) n
  n="$(sed -n 's/^stat::number_of_executed_units: *//p' "$out/$t.out" | head -n1)"
  local verdict="none"
  [ "$status" = 0 ] || verdict="**exit $status**: see $out/work/tissue_fuzz_$t.log"
  echo "| $t | ${n:-?} | $secs | $(( ${n:-0} / (secs > 0 ? secs : 1) )) | $verdict |" >"$out/$t.row"
  return "$status"
}
for t in "${targets[@]}"; do
  one "$t" &
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n || true; done
done
wait
{
  echo "| target | executions | wall s | exec/s (wall) | finding |"
  echo "|---|---|---|---|---|"
  for t in "${targets[@]}"; do cat "$out/$t.row"; done
} >"$out/summary.md"
cat "$out/summary.md"
# A finding or a target not built fails the campaign.
! grep -q -e '\*\*exit' -e 'not built' "$out/summary.md"
