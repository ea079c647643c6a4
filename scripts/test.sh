#!/usr/bin/env bash
# Quick start, step 2: build and run every test (C++ unit tests, Lua API tests, regression and
# convergence runs, datafile smoke tests, the CLI test, the quick benchmark). Extra arguments go
# to ctest, e.g. scripts/test.sh -L unit.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
ctest --test-dir build -j "$(nproc)" --output-on-failure "$@"
