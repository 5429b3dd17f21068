#!/usr/bin/env bash
# tissue-sim on malformed meshes: exactly one line on stderr, naming the file, and exit != 0.
set -u
sim="$1"; dir="$2"; mkdir -p "$dir"
printf 'v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n' > "$dir/nan.obj"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n' > "$dir/range.obj"
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 1\n' > "$dir/degenerate.off"
status=0
for f in nan.obj range.obj degenerate.off missing.obj; do
  "$sim" mesh-info "$dir/$f" >"$dir/out.txt" 2>"$dir/err.txt"; rc=$?
  lines=$(wc -l <"$dir/err.txt")
  if [ "$rc" -eq 0 ] || [ "$lines" -ne 1 ] || ! grep -q "$f" "$dir/err.txt" || [ -s "$dir/out.txt" ]; then
    echo "FAIL $f: exit $rc, $lines stderr lines:"; cat "$dir/err.txt"; status=1
  else
    echo "ok $f: $(cat "$dir/err.txt")"
  fi
done
"$sim" refit-bench --mesh "$dir/nan.obj" --json >/dev/null 2>"$dir/err.txt" && { echo "FAIL refit-bench accepted nan.obj"; status=1; }
exit $status
