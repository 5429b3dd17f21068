#!/usr/bin/env bash
# The 100-frame ParaView series (written by the organ tests' PvdSeries test) opened by ParaView's
# own Python, pvpython: 100 time steps and every point array. Fails (never skips) without a
# working pvpython, saying why: on Debian 12, python3-paraview conflicts with libvtk9-dev and
# python3-vtk9 (the project's VTK), so it cannot be installed beside the build's dependencies;
# run it on a machine with ParaView (and -DTISSUE_TEST_PARAVIEW=ON).
#   pvd_pvpython_test.sh ORGAN_TESTS_BINARY TEST_OUTPUT_DIR pvd_read.py
set -euo pipefail
tests="$1" out="$2" script="$3"
pvpython="${PVPYTHON:-$(command -v pvpython || true)}"
if [ -z "$pvpython" ]; then
  echo "FAIL: pvpython not found: install ParaView with its Python (Debian: paraview python3-paraview;" \
       "it conflicts with libvtk9-dev on Debian 12) or set PVPYTHON=/path/to/pvpython" >&2
  exit 1
fi
"$tests" --gtest_filter='PvdSeries.AHundredFrameRunReadsBackWithEveryArrayAndTimeStep' >/dev/null
pvd="$out/inspect/pvd_series/series/grid.pvd"
run=("$pvpython" --force-offscreen-rendering "$script" "$pvd")
if [ -z "${DISPLAY:-}" ] && command -v xvfb-run >/dev/null; then run=(xvfb-run -a "${run[@]}"); fi
"${run[@]}"
