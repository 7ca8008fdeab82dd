#!/usr/bin/env bash
# README command 2: set-up (including ParaView for the integration tests), build, run every test.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/build.sh"
build="${FLUIDVIZ_BUILD_DIR:-$root/build}"
cd "$build"
ctest --output-on-failure --timeout 900 -j 2 "$@"
