#!/usr/bin/env bash
# The README's quick tour: runs the examples it uses with their own settings and one command per
# tool on their output, and copies the pictures into docs/tour/ (the README shows those).
#   scripts/tour.sh [BUILD_DIR] [WORK]    (defaults: build, /tmp/fluidviz_tour)
# Stops at the first command that fails. The cylinder example is the long one.
set -euo pipefail

ROOT="$(cd "$(dirname "$0")/.." && pwd)"
fluidviz="${1:-$ROOT/build}/apps/fluidviz/fluidviz"
WORK="${2:-/tmp/fluidviz_tour}"
TOUR="$ROOT/docs/tour"
mkdir -p "$WORK" "$TOUR"
cd "$WORK"

# The last file of a .pvd.
last() { echo "$(dirname "$1")/$(grep -o 'file="[^"]*"' "$1" | tail -1 | sed 's/file="\(.*\)"/\1/')"; }
say() { echo "== $*"; }

say "run: the default scene, a four-roll mill (LBM)"
"$fluidviz" run "$ROOT/examples/four_roll_mill.json" -o four --replace
cp four/four_roll_mill_speed.png "$TOUR/run_four_roll_mill_speed.png"
snap=$(last four/four_roll_mill.pvd)

say "lic: Line Integral Convolution of its last snapshot"
"$fluidviz" lic "$snap" -a velocity -o lic.png --color-by vorticity --colormap coolwarm \
  --title "Four-roll mill: LIC coloured by vorticity"
cp lic.png "$TOUR/lic_four_roll_mill.png"

say "streamlines: evenly spaced lines over the speed"
"$fluidviz" streamlines "$snap" -a velocity -o lines.vtp --evenly-spaced 6 --png lines.png \
  --title "Four-roll mill: evenly spaced streamlines"
cp lines.png "$TOUR/streamlines_four_roll_mill.png"

say "topology: the six-roll mill's monkey saddle"
"$fluidviz" run "$ROOT/examples/six_roll_mill.json" -o six --replace
"$fluidviz" topology "$(last six/six_roll_mill.pvd)" -a velocity -o points.vtp --csv points.csv \
  --png topology.png --title "Six-roll mill: critical points and separatrices"
cp topology.png "$TOUR/topology_six_roll_mill.png"

say "resample + isosurface: the dam break's particles onto a grid, its free surface"
"$fluidviz" run "$ROOT/examples/dam_break_2d.json" -o dam --replace
"$fluidviz" resample "$(last dam/dam_break_2d.pvd)" -o dam_grid.vti --png-particles particles.png \
  --color-by speed --up y --azimuth 0 --elevation 0
"$fluidviz" isosurface dam_grid.vti -a color --value 0.5 -o surface.vtp --png surface.png
cp particles.png "$TOUR/resample_dam_break_particles.png"
cp surface.png "$TOUR/isosurface_dam_break_free_surface.png"
cp dam/dam_break_2d_surge_front.png "$TOUR/run_dam_break_surge_front.png"

say "streamlines in 3D: a public CFD field (VTK's office, legacy .vtk)"
"$fluidviz" streamlines "$ROOT/tests/data/vtkdata/office.binary.vtk" -a vectors -o office.vtp \
  --seeds line:0.1,2.1,0.5,0.1,2.7,2.1,12 --tubes 0.08 --context slice:z=10 --png office.png \
  --title "Office air flow: streamtubes from the inlet"
cp office.png "$TOUR/streamlines_3d_office.png"

say "run: the cavity against Ghia et al. 1982, the cylinder's drag and lift"
"$fluidviz" run "$ROOT/examples/lid_driven_cavity.json" -o cavity --replace
ls cavity/*.png
"$fluidviz" run "$ROOT/examples/cylinder_channel.json" -o cylinder --replace
ls cylinder/*.png
