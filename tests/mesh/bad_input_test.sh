#!/usr/bin/env bash
# tissue-sim on malformed meshes: exactly one line on stderr, naming the file, and exit != 0.
set -u
# $3: 1 when tissue-sim was built with VTK (a legacy .vtk surface then loads), 0 when not (it
# must then be refused in one line that says so).
sim="$1"; dir="$2"; with_vtk="${3:-1}"; mkdir -p "$dir"
printf 'v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n' > "$dir/nan.obj"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n' > "$dir/range.obj"
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 1\n' > "$dir/degenerate.off"
# Issue 14: a huge declared count fails at once; VTK's errors are one line; strict refuses a repair.
printf 'OFF\n1000000000000 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n' > "$dir/huge.off"
# The counts split over lines, one beyond 2^64 (found by the OFF fuzz target: it ran out of memory).
printf 'OFF\n 66666666666666666661\n3\n3 03' > "$dir/split.off"
# A negative element count (found by the PLY fuzz target: it wrapped to 2^64 - 4 and looped).
printf 'ply\nformat ascii 1.0\nelement vert -4\nend_header\n0 0 0\n' > "$dir/negative.ply"
printf '# vtk DataFile Version 3.0\nt\nASCII\nDATASET POLYDATA\nPOINTS 4 float\n0 0 0\n' > "$dir/truncated.vtk"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 2 1 0\nf 1 2 3\nf 2 3 4\nf 2 5 4\n' > "$dir/flip.obj"
status=0
for f in nan.obj range.obj degenerate.off missing.obj huge.off split.off negative.ply truncated.vtk "flip.obj --strict"; do
  # shellcheck disable=SC2086 # "flip.obj --strict" is a file and a flag
  set -- $f; f=$1; shift
  timeout 20 "$sim" mesh-info "$dir/$f" "$@" >"$dir/out.txt" 2>"$dir/err.txt"; rc=$?
  lines=$(wc -l <"$dir/err.txt")
  if [ "$rc" -eq 0 ] || [ "$lines" -ne 1 ] || ! grep -q "$f" "$dir/err.txt" || [ -s "$dir/out.txt" ]; then
    echo "FAIL $f: exit $rc, $lines stderr lines:"; cat "$dir/err.txt"; status=1
  else
    echo "ok $f: $(cat "$dir/err.txt")"
  fi
done
# Lenient loading repairs the misoriented face: exit 0, one warning line with the count.
"$sim" mesh-info "$dir/flip.obj" >"$dir/out.txt" 2>"$dir/err.txt"; rc=$?
if [ "$rc" -ne 0 ] || [ "$(wc -l <"$dir/err.txt")" -ne 1 ] || ! grep -q "flip.obj: flipped 1 faces" "$dir/err.txt"; then
  echo "FAIL flip.obj (lenient): exit $rc:"; cat "$dir/err.txt"; status=1
else
  echo "ok flip.obj (lenient): $(cat "$dir/err.txt")"
fi
# A legacy VTK surface (POLYDATA) is described as a surface.
printf '# vtk DataFile Version 3.0\ns\nASCII\nDATASET POLYDATA\nPOINTS 4 float\n0 0 0 1 0 0 1 1 0 0 1 0\nPOLYGONS 1 5\n4 0 1 2 3\n' > "$dir/surface.vtk"
if [ "$with_vtk" = 1 ]; then
  if ! "$sim" mesh-info "$dir/surface.vtk" >"$dir/out.txt" 2>"$dir/err.txt" || ! grep -q "faces: 2" "$dir/out.txt"; then
    echo "FAIL surface.vtk:"; cat "$dir/out.txt" "$dir/err.txt"; status=1
  else
    echo "ok surface.vtk: a surface of 2 faces"
  fi
elif "$sim" mesh-info "$dir/surface.vtk" >"$dir/out.txt" 2>"$dir/err.txt" || [ "$(wc -l <"$dir/err.txt")" -ne 1 ] ||
  ! grep -q "built without VTK" "$dir/err.txt"; then
  echo "FAIL surface.vtk (no VTK): expected one line saying so:"; cat "$dir/out.txt" "$dir/err.txt"; status=1
else
  echo "ok surface.vtk (no VTK): $(cat "$dir/err.txt")"
fi
"$sim" refit-bench --mesh "$dir/nan.obj" --json >/dev/null 2>"$dir/err.txt" && { echo "FAIL refit-bench accepted nan.obj"; status=1; }
exit $status
