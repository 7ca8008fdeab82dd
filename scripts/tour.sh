#!/usr/bin/env bash
# The README's quick tour: runs the examples it uses with their own settings and one command per
# tool on their output, and copies the pictures into docs/tour/ (the README shows those).
#   scripts/tour.sh [BUILD_DIR] [WORK]    (defaults: build, /tmp/fluidviz_tour)
# Stops at the first command that fails. Pictures are 480 px wide (LIC noise does not compress:
# a full-size one is 1 MB). The cylinder example is the long one.
set -euo pipefail

ROOT="$(cd "$(dirname "$0")/.." && pwd)"
fluidviz="$(cd "${1:-$ROOT/build}" && pwd)/apps/fluidviz/fluidviz"
[[ -x $fluidviz ]] || { echo "tour.sh: no $fluidviz; build first (bash scripts/build.sh)"; exit 2; }
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
"$fluidviz" lic "$snap" -a velocity -o lic.png --resolution 480 --color-by vorticity --colormap coolwarm \
  --title "Four-roll mill: LIC coloured by vorticity"
cp lic.png "$TOUR/lic_four_roll_mill.png"

say "streamlines: evenly spaced lines over the speed"
"$fluidviz" streamlines "$snap" -a velocity -o lines.vtp --evenly-spaced 6 --png lines.png --width 480 \
  --title "Four-roll mill: evenly spaced streamlines"
cp lines.png "$TOUR/streamlines_four_roll_mill.png"

say "topology: the six-roll mill's monkey saddle"
"$fluidviz" run "$ROOT/examples/six_roll_mill.json" -o six --replace
"$fluidviz" topology "$(last six/six_roll_mill.pvd)" -a velocity -o points.vtp --csv points.csv \
  --png topology.png --width 480 --title "Six-roll mill: critical points and separatrices"
cp topology.png "$TOUR/topology_six_roll_mill.png"

say "resample + isosurface: the dam break's particles at t = 0.4 s onto a grid, its free surface"
"$fluidviz" run "$ROOT/examples/dam_break_2d.json" -o dam --replace
"$fluidviz" resample dam/dam_break_2d/dam_break_2d_0008.vtp -o dam_grid.vti \
  --png-particles particles.png --color-by speed --azimuth 0 --elevation 0 --size 640x320 --zoom 1.5
"$fluidviz" isosurface dam_grid.vti -a color --value 0.5 -o surface.vtp --png surface.png
cp particles.png "$TOUR/resample_dam_break_particles.png"
cp surface.png "$TOUR/isosurface_dam_break_free_surface.png"
cp dam/dam_break_2d_surge_front.png "$TOUR/run_dam_break_surge_front.png"

say "streamlines in 3D: a public CFD field (VTK's office, legacy .vtk)"
"$fluidviz" streamlines "$ROOT/tests/data/vtkdata/office.binary.vtk" -a vectors -o office.vtp \
  --seeds line:0.1,2.1,0.5,0.1,2.7,0.5,10 --tubes 0.15 --color-by integration_time \
  --colormap inferno --azimuth 40 --elevation 25 --size 640x480 --png office.png \
  --title "Office air flow (VTK data): streamtubes from the inlet, by travel time"
cp office.png "$TOUR/streamlines_3d_office.png"

say "run: the cavity's centreline against Ghia et al. 1982, the cylinder's lift coefficient"
"$fluidviz" run "$ROOT/examples/lid_driven_cavity.json" -o cavity --replace
cp cavity/lid_driven_cavity_u_vertical_centreline.png "$TOUR/run_cavity_centreline_ghia.png"
"$fluidviz" run "$ROOT/examples/cylinder_channel.json" -o cylinder --replace
cp cylinder/cylinder_channel_vorticity.png "$TOUR/run_cylinder_vorticity.png"
cp cylinder/cylinder_channel_lift_coefficient.png "$TOUR/run_cylinder_lift.png"

say "plot: a user's CSV, here the cylinder's drag coefficient column"
"$fluidviz" plot cylinder/cylinder_channel_time_series.csv --y "C_D (1)" -o drag.png \
  --title "Cylinder in a channel: drag coefficient" --width 720 --height 400
cp drag.png "$TOUR/plot_cylinder_drag.png"
echo "pictures in $TOUR"
