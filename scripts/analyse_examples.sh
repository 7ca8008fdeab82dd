#!/usr/bin/env bash
# Runs every example (examples/*.json) with small settings, then the analysis commands with their
# defaults on its last snapshot (issue 16): lic, topology (with a picture), isosurface and, for
# SPH, resample first (the grid's free surface: isosurface -a color --value 0.5). Look at the
# pictures in OUT/<example>/: no noise inside solids, no critical points inside them, no refusal
# of nodes without particles.
#   scripts/analyse_examples.sh [BUILD_DIR] [OUT]    (defaults: build, /tmp/fluidviz_examples)
# Stops at the first command that fails. 2 threads; a few minutes on 2 cores.
set -euo pipefail

ROOT="$(cd "$(dirname "$0")/.." && pwd)"
FLUIDVIZ="${1:-$ROOT/build}/apps/fluidviz/fluidviz"
OUT="${2:-/tmp/fluidviz_examples}"
mkdir -p "$OUT"

# Small settings per example (--set key=value ...), so that each run takes seconds.
settings() {
  case "$1" in
    cylinder_channel) echo "lbm.resolution=220 lbm.end_time=1 output.snapshots=2" ;;
    cylinder_wake) echo "lbm.resolution=160 lbm.end_time=2 output.snapshots=2" ;;
    dam_break_2d) echo "sph.end_time=0.3 output.snapshots=2 output.views=[] output.free_surface=[]" ;;
    dam_break_3d) echo "sph.end_time=0.05 output.snapshots=1 output.views=[] output.grids=[] output.free_surface=[]" ;;
    four_roll_mill) echo "lbm.resolution=80 lbm.end_time=3 output.snapshots=2" ;;
    four_roll_mill_sph) echo "sph.end_time=0.3 output.snapshots=1" ;;
    hydrostatic_tank) echo "sph.end_time=0.05 output.snapshots=1" ;;
    lid_driven_cavity) echo "lbm.resolution=64 lbm.end_time=3 output.snapshots=2" ;;
    lid_driven_cavity_3d) echo "lbm.resolution=16 lbm.end_time=1 output.snapshots=1 output.images=[]" ;;
    poiseuille_channel) echo "lbm.resolution=80 lbm.end_time=20 output.snapshots=2" ;;
    six_roll_mill) echo "lbm.resolution=96 lbm.end_time=3" ;;
    six_roll_mill_sph) echo "sph.end_time=0.2" ;;
    taylor_green) echo "lbm.end_time=0.5 output.snapshots=2" ;;
    two_roll_mill) echo "lbm.resolution=60 lbm.end_time=3" ;;
    *) echo "" ;;
  esac
}

# The last file of a .pvd.
lastSnapshot() { grep -o 'file="[^"]*"' "$1" | tail -1 | sed 's/file="\(.*\)"/\1/'; }

# "colour range [a, b]" of a lic run -> (a + b) / 2, an iso value inside the speed's range.
midRange() { sed -n 's/.*colour range \[\([^,]*\), \([^]]*\)\].*/\1 \2/p' | awk '{print ($1 + $2) / 2}'; }

for scene in "$ROOT"/examples/*.json; do
  name="$(basename "$scene" .json)"
  dir="$OUT/$name"
  rm -rf "$dir"
  set_args=()
  for s in $(settings "$name"); do set_args+=(--set "$s"); done
  echo "== $name"
  nice -n 10 "$FLUIDVIZ" run "$scene" -o "$dir/run" --threads 2 "${set_args[@]}" > "$dir.log" 2>&1 \
    || { cat "$dir.log"; exit 1; }
  grep -E "ended early|steady" "$dir.log" || true
  snapshot="$dir/run/$(lastSnapshot "$dir/run/$name.pvd")"
  grid="$snapshot"
  slice=()
  if [[ "$snapshot" == *.vtp ]]; then
    grid="$dir/grid.vti"
    nice -n 10 "$FLUIDVIZ" resample "$snapshot" -o "$grid" --threads 2
  fi
  nz="$(grep -a -o 'WholeExtent="[^"]*"' "$grid" | head -1 | awk '{print $6}' | tr -d '"')"
  if [[ "$nz" != "0" ]]; then slice=(--slice "z=$((nz / 2))"); fi
  lic="$(nice -n 10 "$FLUIDVIZ" lic "$grid" -a velocity "${slice[@]}" -o "$dir/lic.png")"
  echo "$lic"
  nice -n 10 "$FLUIDVIZ" topology "$grid" -a velocity "${slice[@]}" -o "$dir/points.vtp" \
    --csv "$dir/points.csv" --png "$dir/topology.png"
  if [[ "$snapshot" == *.vtp ]]; then
    nice -n 10 "$FLUIDVIZ" isosurface "$grid" -a color --value 0.5 -o "$dir/surface.vtp" \
      --png "$dir/surface.png"
  else
    value="$(echo "$lic" | midRange)"
    nice -n 10 "$FLUIDVIZ" isosurface "$grid" -a speed --value "$value" -o "$dir/surface.vtp" \
      --png "$dir/surface.png"
  fi
done
echo "pictures in $OUT/<example>/{lic,topology,surface}.png"
