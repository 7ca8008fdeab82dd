#!/usr/bin/env bash
# Builds the fluidviz ParaView plugin (paraview/, issue 17) against Debian's ParaView 5.11, with
# all of its own set-up (scripts/setup.sh, scripts/setup_paraview_dev.sh). Idempotent.
#
#   [FLUIDVIZ_CORES_FILE=build/fluidviz-plugin-cores.cmake] \
#   scripts/build_paraview_plugin.sh [BUILD_DIR]      default: build/paraview-plugin
#
# Prints the plugin's path last. Load it in the ParaView GUI (Tools > Manage Plugins > Load New)
# or in pvpython/pvbatch: LoadPlugin(path, remote=False, ns=globals()). The run tests build it as
# the ctest fixture `paraview_plugin` (tests/CMakeLists.txt).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-${FLUIDVIZ_PLUGIN_BUILD_DIR:-$root/build/paraview-plugin}}
modules=${FLUIDVIZ_PARAVIEW_PYTHON_DIR:-$root/build/paraview-python}
bash "$root/scripts/setup.sh"
paraview_dir=$(bash "$root/scripts/setup_paraview_dev.sh" "$modules" | tail -n 1)
paraview_dir=${paraview_dir#ParaView_DIR=}
# FLUIDVIZ_CORES_FILE: a Release fluidviz build's fluidviz-plugin-cores.cmake, whose VTK-free
# modules the plugin then links instead of compiling them again (paraview/CMakeLists.txt).
cores=${FLUIDVIZ_CORES_FILE:-}
if [[ -n "$cores" && ! -f "$cores" ]]; then
  echo "build_paraview_plugin.sh: FLUIDVIZ_CORES_FILE=$cores does not exist (build fluidviz first)" >&2
  exit 1
fi
cmake -S "$root/paraview" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DParaView_DIR="$paraview_dir" -DFLUIDVIZ_CORES_FILE="$cores" >/dev/null
cmake --build "$build" -j "$(nproc)" >&2
plugin="$build/lib/fluidviz/Fluidviz/Fluidviz.so"
[[ -f "$plugin" ]] || { echo "build_paraview_plugin.sh: no $plugin after the build" >&2; exit 1; }
echo "$plugin"
