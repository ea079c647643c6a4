#!/usr/bin/env bash
# Installs froth's build and test dependencies from Debian 12 packages (nothing else is
# downloaded). Uses sudo when not run as root.
set -euo pipefail
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends \
    g++ cmake ninja-build pkg-config \
    libeigen3-dev libsuitesparse-dev libopenblas0-pthread \
    liblua5.4-dev libreadline-dev libgmsh-dev libcgal-dev libgtest-dev libpng-dev
