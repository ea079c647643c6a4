#!/usr/bin/env bash
# Quick start, step 1: install the dependencies, build, and run the default scene (the seed's
# double bubble relaxing to the standard double bubble, about 40 s on 2 cores).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
build/froth datafiles/double_bubble.lua
