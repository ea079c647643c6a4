#!/usr/bin/env bash
# The sanitizer job of CI: froth built with ASan + UBSan (every finding fatal) into
# ./build-asan, then the unit and lua labels and the reader fuzzer at 100,000 inputs.
# LeakSanitizer's suppressions (ci/lsan.supp) name only leaks inside libraries we do not own.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=None -DCMAKE_CXX_FLAGS="-O1 -g1" -DFROTH_SANITIZE=ON \
      -DFROTH_BUILD_BENCH=OFF -DFROTH_FUZZ_ITERATIONS=100000 >/dev/null
cmake --build build-asan -j "$(nproc)"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1"
export LSAN_OPTIONS="suppressions=$PWD/ci/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
ctest --test-dir build-asan -j "$(nproc)" --output-on-failure -L 'unit|lua|fuzz' "$@"
