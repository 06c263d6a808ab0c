#!/usr/bin/env bash
# A big planar curve costs what its picture costs: `sprout render` of the quadratic Gosper
# curve (ABOP 1.11b) at n=5 (9.8 M segments) against n=3 (15.6 k segments), 640x480, as whole
# processes; best of 5 wall-clock runs each, peak memory of the big one.
# Bars: ratio <= 3, peak memory <= 600 MB.
# The overlapping case (issue 24): 10 M segments going round the edges of one square (`axiom:`
# of 5 M F, `F -> F+F`, 90 degrees), at 640x480 and at 3840x2160, against the Gosper curve n=5
# at 640x480: overdraw costs no more than the segments read once (it took 29 s at 160x120).
#
#   bench/curve_bench.sh     (after scripts/setup.sh; uses GNU time, Debian's `time` package)
set -euo pipefail
cd "$(dirname "$0")/.."
sprout=build/sprout
[ -x "$sprout" ] || { echo "build first: scripts/setup.sh" >&2; exit 1; }
[ -x /usr/bin/time ] || { echo "needs GNU time: apt-get install time" >&2; exit 1; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
run() {  # n [source size] -> "best_seconds peak_kb"
  local best=999 peak=0 line s kb
  for _ in 1 2 3 4 5; do
    line=$(/usr/bin/time -f "%e %M" "$sprout" render "${2:-quadratic_gosper_1_11b}" -n "$1" --size "${3:-640x480}" -o "$work/c.png" 2>&1 >/dev/null | tail -1)
    s=${line% *}; kb=${line#* }
    best=$(awk -v a="$best" -v b="$s" 'BEGIN { print (b < a ? b : a) }')
    (( kb > peak )) && peak=$kb
  done
  echo "$best $peak"
}
read -r small smallKb <<<"$(run 3)"
read -r big bigKb <<<"$(run 5)"
python3 -c "print('angle: 90\naxiom: ' + 'F' * 5000000 + '\nF -> F+F')" > "$work/square.lsys"
read -r square squareKb <<<"$(run 1 "$work/square.lsys" 640x480)"
read -r square4k square4kKb <<<"$(run 1 "$work/square.lsys" 3840x2160)"
# What a 3840x2160 picture costs by itself (the sky and ground drawn, read back, encoded):
# the Koch curve at n=1, 12 segments.
read -r koch4k koch4kKb <<<"$(run 1 koch 3840x2160)"
awk -v g="$big" -v s="$square" -v s4="$square4k" -v k4="$koch4k" -v m="$square4kKb" 'BEGIN {
  printf "curve_bench: overlapping square (10 M segments) %.2f s at 640x480, %.2f s at 3840x2160 (peak %.0f MB; a 12-segment curve takes %.2f s at that size): ratio to Gosper n=5 %.2f and %.2f\n", s, s4, m / 1024, k4, s / g, s4 / g }'
awk -v s="$small" -v b="$big" -v m="$bigKb" 'BEGIN {
  printf "curve_bench: quadratic Gosper n=5 (9.8 M segments) %.2f s, n=3 (15.6 k segments) %.2f s: ratio %.2f (bar <= 3); peak memory %.0f MB (bar <= 600)\n", b, s, b / s, m / 1024;
  exit !(b / s <= 3 && m / 1024 <= 600) }'
