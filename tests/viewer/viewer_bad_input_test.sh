#!/usr/bin/env bash
# tissue-viewer on bad input: exactly one line on stderr, exit code 1 or 2, no core dump.
set -u
viewer="$1"; dir="$2"; mkdir -p "$dir"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' > "$dir/no_uvs.obj"
status=0
check() {  # check NAME EXPECTED-TEXT COMMAND...
  local name="$1" expect="$2"; shift 2
  "$@" >"$dir/out.txt" 2>"$dir/err.txt"; local rc=$?
  local lines; lines=$(wc -l <"$dir/err.txt")
  if [ "$rc" -ne 1 ] && [ "$rc" -ne 2 ] || [ "$lines" -ne 1 ] || ! grep -q -- "$expect" "$dir/err.txt"; then
    echo "FAIL $name: exit $rc, $lines stderr lines:"; cat "$dir/err.txt"; status=1
  else
    echo "ok $name: $(cat "$dir/err.txt")"
  fi
}
check no-display "run under a display or xvfb-run" env -u DISPLAY -u WAYLAND_DISPLAY "$viewer" --frames 1
check missing-mesh "missing.obj" env -u DISPLAY "$viewer" --mesh "$dir/missing.obj" --frames 1
check no-uvs "no_uvs.obj" env -u DISPLAY "$viewer" --mesh "$dir/no_uvs.obj" --frames 1
check bad-option "--frames" "$viewer" --frames -3
check bad-method "--method" "$viewer" --method ray-march --frames 1
exit $status
