#!/usr/bin/env bash
# `sprout expand` as a whole process against two baselines measured in the same run:
#   - `cat` of the same bytes from a file, into the same pipe (bar: sprout within 3x of it);
#   - the npm `lindenmayer` library deriving the same string in memory, no output at all
#     (bar: sprout at least 20x faster).
# The fractal plant (ABOP 1.24f) at n=11: 25.9 M modules. Best of 7 wall-clock runs each.
#
#   bench/expand_bench.sh            (after scripts/setup.sh; installs lindenmayer into bench/tools)
set -euo pipefail
cd "$(dirname "$0")/.."
sprout=build/sprout
[ -x "$sprout" ] || { echo "build first: scripts/setup.sh" >&2; exit 1; }
[ -d bench/tools/node_modules/lindenmayer ] ||
  npm install --prefix bench/tools --no-audit --no-fund --loglevel=error >/dev/null
n=11
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
"$sprout" expand fractal_plant -n $n >"$work/string.txt"
bytes=$(wc -c <"$work/string.txt")
[ "$(node bench/tools/lindenmayer_derive.js $n)" -eq $((bytes - 1)) ] || { echo "lindenmayer derived another string" >&2; exit 1; }

best() {  # best wall time in ms of a shell command, over 7 runs
  local best=999999 t0 t1 ms
  for _ in 1 2 3 4 5 6 7; do
    t0=$(date +%s%N); bash -c "$1" >/dev/null; t1=$(date +%s%N)
    ms=$(( (t1 - t0) / 1000 ))
    (( ms < best )) && best=$ms
  done
  echo "$best"
}
s=$(best "$sprout expand fractal_plant -n $n | wc -c")
c=$(best "cat $work/string.txt | wc -c")
l=$(best "node bench/tools/lindenmayer_derive.js $n")
awk -v s="$s" -v c="$c" -v l="$l" -v b="$bytes" 'BEGIN {
  printf "expand_bench: fractal plant n=11, %.1f MB: sprout expand %.1f ms, cat of the same bytes %.1f ms, lindenmayer (npm, in memory) %.1f ms\n", b / 1e6, s / 1000, c / 1000, l / 1000;
  printf "  sprout / cat = %.2f (bar <= 3), lindenmayer / sprout = %.1f (bar >= 20)\n", s / c, l / s;
  exit !(s / c <= 3 && l / s >= 20) }'
