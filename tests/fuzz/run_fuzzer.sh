#!/usr/bin/env bash
# One fuzz pass: tests/fuzz/run_fuzzer.sh FUZZER SEEDS_DIR WORK_DIR SECONDS [RUNS]
# Runs libFuzzer for SECONDS (or RUNS executions when given) on a working corpus WORK_DIR that
# starts from the committed seeds (the seeds are never written). Bounded per input: 10 s and
# 2 GiB (a slower or larger input is a finding). Exit 0 only without a crash, leak, timeout or
# out-of-memory; the final line gives the executions done.
set -euo pipefail
fuzzer="$1" seeds="$2" work="$3" seconds="$4" runs="${5:--1}"
mkdir -p "$work"
artifacts="$work/../artifacts-$(basename "$fuzzer")/"
mkdir -p "$artifacts"
"$fuzzer" -max_total_time="$seconds" -runs="$runs" -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=2048 \
  -max_len=65536 -print_final_stats=1 -artifact_prefix="$artifacts" "$work" "$seeds" 2>&1 | tail -n 25
exit "${PIPESTATUS[0]}"
