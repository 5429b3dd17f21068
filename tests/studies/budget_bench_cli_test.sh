#!/usr/bin/env bash
# tissue-sim budget-bench end to end, shortened (a tiny image, a few frames, a short truth): the
# JSON's results are at least three budgets, strictly increasing, each with finite frame times and
# errors against the truth, and "lower" only beyond the truth's noise; a bad budget is one line on stderr and a non-zero exit, at once.
set -u
sim="$1"; dir="$2"; rm -rf "$dir"; mkdir -p "$dir"
status=0
fail() { echo "FAIL $*"; status=1; }

"$sim" --json budget-bench --width 32 --height 24 --frames 3 --warmup 2 --spp 8 --truth-seconds 2 \
  --out "$dir/bench" >"$dir/bench.json" 2>"$dir/bench.err" || { fail "budget-bench exit $?"; cat "$dir/bench.err"; }
[ -s "$dir/bench/budget_bench.json" ] || fail "budget-bench --out wrote no budget_bench.json"
python3 - "$dir/bench/budget_bench.json" <<'PY' || fail "budget-bench results out of range"
import json, math, sys
results = json.load(open(sys.argv[1]))["results"]
assert isinstance(results, list) and len(results) >= 3, results
keys = ["budget_ms", "frame_ms_median", "frame_ms_p95", "rel_rms", "fixed_best_rel_rms"]
for r in results:
    for k in keys:
        assert k in r, (k, r)
    # fixed_best_rel_rms is null when no single setting fits the budget; otherwise an error.
    for k in keys:
        v = r[k]
        if k == "fixed_best_rel_rms" and v is None:
            continue
        assert isinstance(v, (int, float)) and math.isfinite(v), (k, r)
    assert r["budget_ms"] > 0 and 0 < r["frame_ms_median"] <= r["frame_ms_p95"], r
    assert 0 < r["rel_rms"] < 10, r
    if r["fixed_best_rel_rms"] is not None:
        assert 0 < r["fixed_best_rel_rms"] < 10, r
        # "Lower" only by more than two standard errors of the truth's noise on the difference.
        d, s = r["squared_difference"], r["squared_difference_stderr"]
        assert math.isfinite(d) and math.isfinite(s) and s >= 0, r
        assert abs(d - (r["rel_rms"] ** 2 - r["fixed_best_rel_rms"] ** 2)) < 1e-6, r
        assert r["beats_fixed"] == (d < -2 * s) and r["loses_to_fixed"] == (d > 2 * s), r
budgets = [r["budget_ms"] for r in results]
assert all(a < b for a, b in zip(budgets, budgets[1:])), budgets
# The loosest budget fits some fixed setting (the budgets come from their measured times).
assert results[-1]["fixed_best_rel_rms"] is not None, results[-1]
bench = json.load(open(sys.argv[1]))
# Every pixel the truth covers (its centre ray meets the scene) shows exactly one organ: the
# per-organ masks (budget_bench_pixels) partition the covered pixels, and the pixels off every
# silhouette are among them.
counts, truth = bench["organ_pixel_counts"], bench["truth"]
assert len(counts) == len(bench["organs"]) == 5, counts
assert all(isinstance(c, int) and c >= 0 for c in counts), counts
assert sum(counts) == truth["organ_pixels"], (counts, truth)
assert 0 <= truth["organ_pixels_off_silhouettes"] <= truth["organ_pixels"], truth
# Each controller run records its timed frames, the frames its plan changed in, and the
# medians above come from them.
for run, r in zip(bench["controller"], results):
    ms = sorted(run["frame_ms"])
    assert len(ms) == bench["timed_frames"] and all(m > 0 for m in ms), run
    assert ms[math.ceil(0.5 * len(ms)) - 1] == r["frame_ms_median"], (ms, r)
    assert all(0 <= f < len(ms) for f in run["plan_change_frames"]), run
    assert all(0 <= f < bench["warmup_frames"] for f in run["warmup_plan_change_frames"]), run
    assert len(run["plan_change_frames"]) + len(run["warmup_plan_change_frames"]) <= run["plan_changes"], run
    # Per timed frame, the plan's prediction and the budget it was made for (the last frame's
    # are the run's).
    pred, planned = run["frame_predicted_ms"], run["frame_planned_for_ms"]
    assert len(pred) == len(planned) == len(ms) and all(p > 0 for p in pred), run
    assert all(0 < p <= r["budget_ms"] + 1e-9 for p in planned), run
    assert math.isclose(pred[-1], run["predicted_ms"], rel_tol=1e-9), run
    assert run["switches_deferred"] >= 0, run
    # The plan is made for the budget less the tail's share, never for more than the budget.
    assert 0 < run["planned_for_ms"] <= r["budget_ms"] + 1e-9, (run, r)
    assert run["predicted_ms"] > 0, run
    # What the controller believed: every option's cost and expected error on each organ, and
    # for the option it chose, the expected error its choice reports (its cost is learned once
    # more from the frame after the choice: not compared).
    assert run["learned_overhead_ms"] >= 0, run
    learned = {l["method"] + " " + l["setting"]: l for l in run["learned_costs"]}
    assert len(learned) == len(run["learned_costs"]) > 0, run["learned_costs"]
    for l in run["learned_costs"]:
        assert len(l["organ_ms"]) == len(l["organ_expected_rel_rms"]) == 5, l
        assert all(m >= 0 for m in l["organ_ms"]) and l["pass_ms"] >= 0 and l["samples"] >= 0, l
    for i, ch in enumerate(run["choices"]):
        l = learned[ch["method"] + " " + ch["setting"]]
        assert math.isclose(l["organ_expected_rel_rms"][i], ch["expected_rel_rms"], rel_tol=1e-9), (l, ch)
for f in bench["fixed"]:
    assert f["first_frame_ms"] > 0, f
# The best fixed setting that fits has its p95 within the budget itself; the one reported beside
# it within 1.1 x the budget, never worse (it is chosen from more settings).
p95 = {f["method"] + " " + f["setting"]: f["frame_ms_p95"] for f in bench["fixed"]}
for r in results:
    if r["fixed_best"]:
        assert p95[r["fixed_best"]] <= r["budget_ms"], r
        assert r["fixed_best_within_10_percent_rel_rms"] <= r["fixed_best_rel_rms"], r
    if r["fixed_best_within_10_percent"]:
        assert p95[r["fixed_best_within_10_percent"]] <= 1.1 * r["budget_ms"], r
PY

# Bad input: refused before any replay or truth, in one line.
for args in "budget-bench --budgets -5" "budget-bench --budgets 10,0" "budget-bench --width 0"; do
  start=$(date +%s)
  $sim $args >"$dir/out.txt" 2>"$dir/err.txt"; rc=$?
  if [ "$rc" -eq 0 ] || [ "$(wc -l <"$dir/err.txt")" -ne 1 ]; then fail "$args: exit $rc"; cat "$dir/err.txt"; fi
  [ $(( $(date +%s) - start )) -lt 20 ] || fail "$args: refused only after $(( $(date +%s) - start )) s"
done
grep -q "budget" "$dir/err.txt" || fail "a bad size names nothing: $(cat "$dir/err.txt")"
[ "$status" -eq 0 ] && echo "ok"
exit $status
