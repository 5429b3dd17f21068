#!/usr/bin/env bash
# tissue-sim render --method separable --rank R: every component of a rank-R kernel reaches the
# renderer (a blur pass pair each), and a rank a model cannot take is one line on stderr.
set -u
sim="$1"; dir="$2"; rm -rf "$dir"; mkdir -p "$dir"
status=0
fail() { echo "FAIL $*"; status=1; }

for case in "svd 3" "deon 2"; do
  set -- $case
  "$sim" render --method separable --kernel "$1" --rank "$2" --width 96 --height 72 --samples 4 \
    --out "$dir/$1$2.png" --json >"$dir/$1$2.json" || fail "render --kernel $1 --rank $2: exit $?"
  grep -q "\"rank\": $2" "$dir/$1$2.json" || fail "--kernel $1 --rank $2: no \"rank\": $2"
  last=$(($2 - 1))
  grep -q "\"separable:blur-y:$last\"" "$dir/$1$2.json" || fail "--kernel $1 --rank $2: no pass blur-y:$last"
  grep -q "\"separable:blur-y:$2\"" "$dir/$1$2.json" && fail "--kernel $1 --rank $2: a pass pair too many"
  grep -q '"separable:resolve"' "$dir/$1$2.json" || fail "--samples 4: no separable:resolve pass"
  [ -s "$dir/$1$2.png" ] || fail "--kernel $1 --rank $2 wrote no image"
done

for args in "--kernel preintegrated --rank 2" "--kernel svd --rank 9"; do
  "$sim" render --method separable $args --width 32 --height 32 --out "$dir/bad.png" >"$dir/out.txt" 2>"$dir/err.txt"
  rc=$?
  if [ "$rc" -eq 0 ] || [ "$(wc -l <"$dir/err.txt")" -ne 1 ] || ! grep -q -- "--rank" "$dir/err.txt"; then
    fail "$args: exit $rc"; cat "$dir/err.txt"
  fi
done
[ "$status" -eq 0 ] && echo "ok"
exit $status
