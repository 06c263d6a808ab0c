#!/usr/bin/env bash
# The curve editor's drag on L-Py's lsystem9.lpy (issue 52), in the window on software GL (Xvfb
# and Mesa's llvmpipe) at 1440x860: a point of its `branchpath` dragged over 30 frames, a step a
# frame, the model derived again on the worker as it moves (a step waits for the one running).
# Printed, from the script's curve-drag-stats: the longest frame while dragging (the panel, the
# view, the swap: the window stays responsive while the worker derives), the time from the
# drag's last step to the refined plant drawn whole, where that time went (the worker's
# derivation, the still picture, when the last result came) and how many plants were drawn
# while the point moved, in how long (drag_ms); then the same for a drag of the 6-point
# curve of a small model of this bench's own, as the baseline measured in the same run, and the
# ratios. Bars (issue 52): frames within the moving-frame budget (17 ms), refined <= 150 ms.
#
#   bench/curve_drag_bench.sh [MODEL CURVE]   (after scripts/setup.sh; needs xvfb-run and ../shared)
set -euo pipefail
cd "$(dirname "$0")/.."
sprout="$PWD/build/sprout"
[ -x "$sprout" ] || { echo "build first: scripts/setup.sh" >&2; exit 1; }
command -v xvfb-run >/dev/null || { echo "needs xvfb-run (Debian's xvfb)" >&2; exit 1; }
model="${1:-$PWD/../shared/corpus/lpy/tutorial/lpy-paper12-examples/lsystem9.lpy}"
curve="${2:-branchpath}"
[ -f "$model" ] || { echo "no model $model" >&2; exit 1; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export XDG_CACHE_HOME="$work/cache" HOME="$work"
cp "$model" "$work/model.lpy"
# The baseline: a stem along a curve, a dozen modules.
printf '%s\n' "Axiom: _(0.1) SetGuide(path, 6) nF(6, 0.2)" "derivation length: 0" "production:" "endlsystem" \
  "###### INITIALISATION ######" "" "__lpy_code_version__ = 1.1" "" "def __initialiseContext__(context):" \
  "	import openalea.plantgl.all as pgl" "	path = pgl.NurbsCurve2D(" \
  "	    ctrlPointList = pgl.Point3Array([(-0.5, 0, 1),(-0.3, 0.05, 1),(-0.1, 0, 1),(0.1, 0.05, 1),(0.3, 0, 1),(0.5, 0.05, 1)]) , " \
  "	    )" "	context[\"path\"] = path" >"$work/base.lpy"
drag() {  # file curve -> "curve_drag_worst_frame_ms=W refined_ms=R"
  printf 'trust yes\nwait\nsleep 1\nwait\ncurve-drag %s 1 0.02 0.1 30\nwait\ncurve-drag-stats\nquit\n' "$2" >"$work/script.txt"
  (cd "$work" && xvfb-run -a -s '-screen 0 1600x1000x24' "$sprout" "$1" --size 1440x860 --script "$work/script.txt") 2>/dev/null |
    grep '^curve_drag_worst_frame_ms='
}
base="$(drag "$work/base.lpy" path)"
it="$(drag "$work/model.lpy" "$curve")"
echo "baseline (6-point path, one stem): $base"
echo "$(basename "$model") ($curve): $it"
awk -v a="$base" -v b="$it" 'BEGIN {
  split(a, x, /[= ]/); split(b, y, /[= ]/);
  printf "ratios to the baseline: worst frame %.2fx, refined %.2fx\n", y[2] / x[2], y[4] / x[4] }'
