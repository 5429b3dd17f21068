#!/usr/bin/env bash
# tissue-sim's texture-space commands through the pipeline: render --method texture-space (its
# passes in the JSON, a PNG), sss-bench's texture-space rows (keys of the issue, and an image RMS
# within 10% of the reference, as the separable rows), bad options as one line on stderr.
set -u
sim="$1"; dir="$2"; rm -rf "$dir"; mkdir -p "$dir"
status=0
fail() { echo "FAIL $*"; status=1; }

"$sim" render --method texture-space --width 96 --height 72 --samples 0 --out "$dir/tsd.png" --json \
  >"$dir/render.json" || fail "render --method texture-space exit $?"
[ -s "$dir/tsd.png" ] || fail "render wrote no PNG"
for key in '"method": "texture-space"' 'texture-space:irradiance' 'texture-space:blur' 'texture-space:final'; do
  grep -q "$key" "$dir/render.json" || fail "render --json lacks $key"
done

"$sim" sss-bench --json --width 96 --height 72 --frames 1 >"$dir/bench.json" || fail "sss-bench exit $?"
for key in '"method": "texture-space"' '"setting": "2-gaussians"' '"setting": "4-gaussians"' \
           '"setting": "6-gaussians"' '"image_rms"' '"ms"'; do
  grep -q "$key" "$dir/bench.json" || fail "sss-bench --json lacks $key"
done
if command -v python3 >/dev/null; then
  python3 - "$dir/bench.json" <<'PY' || fail "sss-bench texture-space rows out of range"
import json, math, sys
rows = [r for r in json.load(open(sys.argv[1]))["results"] if r["method"] == "texture-space"]
assert len(rows) == 3, rows
for r in rows:
    assert r["ms"] > 0 and math.isfinite(r["image_rms"]), r
    assert r["relative_rms"] < 0.1, r  # the same reference as the separable rows
PY
fi

for args in "render --method texture-space --gaussians 9 --out $dir/x.png" \
            "render --method texture-space --map-size 8 --out $dir/x.png"; do
  $sim $args >"$dir/out.txt" 2>"$dir/err.txt"; rc=$?
  if [ "$rc" -eq 0 ] || [ "$(wc -l <"$dir/err.txt")" -ne 1 ]; then fail "$args: exit $rc"; cat "$dir/err.txt"; fi
done
[ "$status" -eq 0 ] && echo "ok"
exit $status
