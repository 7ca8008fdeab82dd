#!/usr/bin/env bash
# docs/images/fhp_vs_lbm.png: the four-roll mill at t = 60 s, the FHP lattice gas
# (examples/four_roll_mill_fhp.json) on the left, the LBM (examples/four_roll_mill.json) on the
# right, both as LIC coloured by speed. The LBM's steady-state stop is switched off so that both
# pictures show the same time.
# The two pictures differ in height by a few pixels (their titles), so the left one is scaled to
# the right one's height before they are put side by side; the pair is scaled to 1400 pixels
# wide (the LIC texture compresses badly: about 1.2 MB instead of 2.8 MB).
# Usage: scripts/fhp_vs_lbm.sh [BUILD_DIR] [WORK_DIR]   (needs ffmpeg)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build}"
work="${2:-$(mktemp -d)}"
app="$build/apps/fluidviz/fluidviz"
"$app" run "$root/examples/four_roll_mill_fhp.json" -o "$work/fhp" --replace
"$app" run "$root/examples/four_roll_mill.json" -o "$work/lbm" --replace \
  --set lbm.steady_tolerance=0
ffmpeg -y -loglevel error -i "$work/fhp/four_roll_mill_fhp_lic_speed.png" \
  -i "$work/lbm/four_roll_mill_lic_speed.png" \
  -filter_complex "[0:v][1:v]scale2ref=w=oh*mdar:h=ih[fhp][lbm];[fhp][lbm]hstack,scale=1400:-2" \
  "$root/docs/images/fhp_vs_lbm.png"
echo "wrote $root/docs/images/fhp_vs_lbm.png (runs in $work)"
