#!/usr/bin/env bash
# README command 1: set-up, build, and run the default example scene (four-roll mill) into out/.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/build.sh"
cd "$root"
"${FLUIDVIZ_BUILD_DIR:-$root/build}/apps/fluidviz/fluidviz" run examples/four_roll_mill.json -o out --replace "$@"
