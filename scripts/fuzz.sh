#!/usr/bin/env bash
# Fuzzing: builds the libFuzzer targets with clang (core only, ASan + UBSan) and runs each for
# a bounded time. An input may take 30 s (-timeout): the slowest seed, a degenerate 2,000-point
# polygon whose triangulation is bounded (fuzz/regressions/turtle), takes 6.5 s under ASan alone
# and timed out at 10 s with both cores busy. Fails on any crash, sanitizer report, leak or
# timeout; the input that did it is left in build-fuzz/artifacts/ (add it to
# fuzz/regressions/TARGET/, which ctest replays).
#
#   scripts/fuzz.sh [SECONDS_PER_TARGET [TARGET...]]   (default 60, every target)
#
# A long campaign on two cores runs two halves side by side, e.g.
#   scripts/fuzz.sh 1200 parser expr derive turtle & scripts/fuzz.sh 1200 lparser fractint png cpfg lpy vlab enviro image
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
targets=("${@:2}")
((${#targets[@]})) || targets=(parser expr derive turtle lparser fractint png cpfg lpy vlab enviro image)
jobs="$(nproc 2>/dev/null || echo 2)"
for p in clang libclang-rt-14-dev; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ -n "${missing[*]:-}" ]; then
  sudo=""; [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSPROUT_FUZZ=ON \
  -DSPROUT_BUILD_TESTS=OFF -DSPROUT_BUILD_BENCH=OFF >/dev/null
cmake --build build-fuzz -j"$jobs"

shared=../shared/corpus
seeds() {  # the seed corpus of one target: directories libFuzzer reads (recursively)
  case "$1" in
    parser|derive|turtle) echo presets tests/bad-input tests/extreme tests/notation fuzz/seeds/environment fuzz/seeds/drawing fuzz/regressions/"$1" ;;
    expr) echo fuzz/seeds/expr fuzz/regressions/expr ;;
    lparser) echo tests/data/seed001 fuzz/regressions/lparser; [ -d "$shared/lparser" ] && echo "$shared/lparser" ;;
    fractint) echo fuzz/seeds/fractint fuzz/regressions/fractint; [ -d "$shared" ] && echo "$shared" ;;
    png) echo tests/golden fuzz/regressions/png ;;
    vlab) echo fuzz/seeds/vlab; [ -d "$shared/vlab-manuals" ] && echo "$shared/vlab-manuals" ;;
    enviro) echo fuzz/regressions/enviro ;;
    image) echo fuzz/seeds/image fuzz/regressions/image ;;
    cpfg) echo tests/cpfg tests/explorer tests/bad-input presets fuzz/regressions/cpfg ;;
    lpy) echo tests/lpy/models tests/cpfg fuzz/regressions/lpy; [ -d "$shared/lpy" ] && echo "$shared/lpy" ;;
  esac
}
mkdir -p build-fuzz/artifacts
status=0
for t in "${targets[@]}"; do
  corpus=build-fuzz/corpus/$t
  mkdir -p "$corpus" fuzz/regressions/"$t"
  dirs=()
  for d in $(seeds "$t"); do [ -d "$d" ] && dirs+=("$d"); done
  echo "== fuzz_$t for ${seconds}s (seeds: ${dirs[*]})"
  if ! ASAN_OPTIONS=detect_leaks=1 ./build-fuzz/fuzz/fuzz_$t -max_total_time="$seconds" -timeout=30 -rss_limit_mb=2048 \
      -max_len=65536 -dict=fuzz/lsys.dict -print_final_stats=1 -artifact_prefix=build-fuzz/artifacts/$t- \
      "$corpus" "${dirs[@]}" 2>build-fuzz/$t.log; then
    echo "fuzz_$t FAILED:"
    grep -E "ERROR|SUMMARY|runtime error|Test unit written|fuzz check failed|^cylinder|terminate called|what\(\)" \
      build-fuzz/$t.log | head -20
    # The input, so that a find on a machine that keeps nothing can be replayed (base64 -d).
    unit="$(sed -n 's/.*Test unit written to \(.*\)$/\1/p' build-fuzz/$t.log | tail -1)"
    if [ -n "$unit" ] && [ -f "$unit" ]; then
      echo "the input ($(stat -c %s "$unit") bytes; first 16 KB, base64):"
      head -c 16384 "$unit" | base64 -w 120
    fi
    status=1
  fi
  grep -E "stat::number_of_executed_units|stat::peak_rss_mb" build-fuzz/$t.log | tr '\n' ' '; echo
done
exit $status
