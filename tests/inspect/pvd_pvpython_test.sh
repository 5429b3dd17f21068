#!/usr/bin/env bash
# The 100-frame ParaView series (written by the organ tests' PvdSeries test) opened by ParaView's
# own Python: 100 increasing time steps and every point array, through ParaView's PVD reader.
# Runs pvpython, or pvbatch (Debian's paraview package) with the ParaView Python modules that
# scripts/install-deps.sh --paraview unpacks into /opt/tissue-paraview (Debian 12's python3-paraview
# conflicts with the libvtk9-dev this build needs, so it is not installed). Fails, never skips,
# when neither is there, saying how to get it. Set PVPYTHON to use another one.
#   pvd_pvpython_test.sh ORGAN_TESTS_BINARY TEST_OUTPUT_DIR pvd_read.py
set -euo pipefail
tests="$1" out="$2" script="$3"
unpacked=/opt/tissue-paraview/usr/lib/python3/dist-packages
pv="${PVPYTHON:-}"
if [ -z "$pv" ] && command -v pvpython >/dev/null; then pv="$(command -v pvpython)"; fi
if [ -z "$pv" ] && command -v pvbatch >/dev/null && [ -d "$unpacked/paraview" ]; then
  pv="$(command -v pvbatch)"
  export PYTHONPATH="$unpacked${PYTHONPATH:+:$PYTHONPATH}"
fi
if [ -z "$pv" ]; then
  echo "FAIL: no ParaView Python (pvpython, or pvbatch with $unpacked): run scripts/install-deps.sh --paraview" \
       "as root, or set PVPYTHON=/path/to/pvpython" >&2
  exit 1
fi
"$tests" --gtest_filter='PvdSeries.AHundredFrameRunReadsBackWithEveryArrayAndTimeStep' >/dev/null
"$pv" "$script" "$out/inspect/pvd_series/series/grid.pvd"
