#!/usr/bin/env bash
# One fuzz pass: tests/fuzz/run_fuzzer.sh FUZZER SEEDS_DIR WORK_DIR SECONDS [RUNS [SEED]]
# Runs libFuzzer for RUNS executions (-1: no limit), at most SECONDS, with libFuzzer's SEED
# (default 0: a random one) on a working corpus WORK_DIR that starts from the committed seeds (the
# seeds are never written). With RUNS given the working corpus starts afresh, so a pass with a
# fixed SEED is reproducible: the test suite's short pass (RUNS 60000, SEED 1) executes the same
# inputs on every machine that finishes it inside SECONDS, and a pass that fails on CI fails the
# same way here. Bounded per input: 10 s and
# 2 GiB (a slower or larger input is a finding). Exit 0 only without a crash, leak, timeout or
# out-of-memory; the final line gives the executions done. The whole output is kept in
# WORK_DIR/../<fuzzer>.log (a finding's report starts far above the last lines shown).
#
# The VTK targets (tissue_fuzz_vtk, tissue_fuzz_vtu) are fuzzed with libFuzzer's per-input leak
# check off and then the whole working corpus is replayed once with it on. VTK 9.1's readers keep
# allocations across reads, so with the check on libFuzzer re-runs nearly every input under a full
# LeakSanitizer scan; and VTK (no frame pointers) needs the slow unwinder for its leak stacks to
# name a function, which costs another factor of six. The replay has both, and
# tests/sanitizers/lsan_vtk.supp names VTK's own leaks (docs/DECISIONS.md).
set -euo pipefail
fuzzer="$1" seeds="$2" work="$3" seconds="$4" runs="${5:--1}" seed="${6:-0}"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
[ "$runs" -gt 0 ] && rm -rf "$work"
mkdir -p "$work"
artifacts="$work/../artifacts-$(basename "$fuzzer")/"
mkdir -p "$artifacts"
log="$work/../$(basename "$fuzzer").log"
: >"$log"
limits=(-seed="$seed" -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=2048 -max_len=65536 -artifact_prefix="$artifacts")
case "$(basename "$fuzzer")" in
  tissue_fuzz_vtk | tissue_fuzz_vtu) vtk=1 ;;
  *) vtk=0 ;;
esac
if [ "$vtk" = 0 ]; then
  "$fuzzer" -max_total_time="$seconds" -runs="$runs" "${limits[@]}" -print_final_stats=1 "$work" "$seeds" 2>&1 |
    tee -a "$log" | tail -n 25
  exit "${PIPESTATUS[0]}"
fi
ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0" "$fuzzer" -max_total_time="$seconds" -runs="$runs" \
  -detect_leaks=0 "${limits[@]}" -print_final_stats=1 "$work" "$seeds" 2>&1 | tee -a "$log" | tail -n 25
status="${PIPESTATUS[0]}"
[ "$status" = 0 ] || exit "$status"
echo "leak pass: every input of $work once, LeakSanitizer with full stacks"
ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}fast_unwind_on_malloc=0" \
  LSAN_OPTIONS="suppressions=$here/../sanitizers/lsan_vtk.supp:print_suppressions=1" \
  "$fuzzer" -runs=0 "${limits[@]}" "$work" 2>&1 | tee -a "$log" | tail -n 40
exit "${PIPESTATUS[0]}"
