#!/usr/bin/env bash
# The sanitizer jobs: the whole test suite built with AddressSanitizer + UndefinedBehaviorSanitizer
# (with float-cast-overflow, which GCC's 'undefined' leaves out: a double out of an integer's
# range cast to it, issue 26), and the core and viewer-logic tests (the viewer derives on a worker thread) with
# ThreadSanitizer. Any report fails. Run after scripts/setup.sh test (which installs the packages).
#
#   scripts/sanitize.sh [asan|tsan|all]   (default all)
set -euo pipefail
cd "$(dirname "$0")/.."
what="${1:-all}"
jobs="$(nproc 2>/dev/null || echo 2)"
supp="$PWD/tests/sanitizers/lsan.supp"

if [ "$what" = asan ] || [ "$what" = all ]; then
  cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSPROUT_SANITIZE=address,undefined,float-cast-overflow -DSPROUT_BUILD_BENCH=OFF >/dev/null
  cmake --build build-asan -j"$jobs"
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  # Leaks inside Mesa and the X stack are theirs (see the suppressions file).
  LSAN_OPTIONS="suppressions=$supp:print_suppressions=0" ctest --test-dir build-asan --output-on-failure -j"$jobs" -E '^Window\.'
  # The window under Xvfb loads and unloads GL drivers whose leaks cannot be attributed:
  # memory errors and undefined behaviour are still checked there.
  ASAN_OPTIONS=detect_leaks=0 ctest --test-dir build-asan --output-on-failure -R '^Window\.'
fi

if [ "$what" = tsan ] || [ "$what" = all ]; then
  cmake -S . -B build-tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSPROUT_SANITIZE=thread -DSPROUT_BUILD_BENCH=OFF >/dev/null
  cmake --build build-tsan -j"$jobs" --target core_tests viewer_tests
  export TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1
  ./build-tsan/tests/core_tests --gtest_brief=1
  ./build-tsan/tests/viewer_tests --gtest_brief=1
fi
echo "sanitizers: no reports"
