#!/usr/bin/env bash
# README command 2: set-up (including ParaView for the integration tests), build, run every test.
# Stage 1: the Release build in build/ and its whole suite. Stage 2 (scripts/sanitize.sh, issue 8):
# the whole suite again under AddressSanitizer + UndefinedBehaviorSanitizer in build-asan/, with
# short libFuzzer runs of the scene and .vti/.vtp readers (60000 inputs each from a fixed seed).
# FLUIDVIZ_SKIP_SANITIZE=1 runs stage 1 only (a quick local check; CI runs both).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/build.sh"
build="${FLUIDVIZ_BUILD_DIR:-$root/build}"
cd "$build"
ctest --output-on-failure --timeout 900 -j 2 "$@"
if [[ "${FLUIDVIZ_SKIP_SANITIZE:-0}" != 1 ]]; then
  bash "$root/scripts/sanitize.sh" "$@"
fi
