#!/usr/bin/env bash
# Makes Debian's ParaView usable for building the fluidviz ParaView plugin (paraview/). Idempotent.
#
#   scripts/setup_paraview_dev.sh DIR
#
# 1. scripts/setup_paraview.sh DIR: pvbatch, and python3-paraview extracted into DIR/usr.
# 2. Installs Debian's `paraview-dev` with apt-get if its CMake package is missing.
# 3. Installs openmpi-bin (mpirun) if missing, for the plugin's parallel tests.
# 4. Writes DIR/cmake/paraview-5.11: a copy of that CMake package which configures on this
#    machine, and prints `ParaView_DIR=...` last on stdout.
#
# Why a copy: Debian 12's ParaView CMake package does not configure as shipped. Its imported
# targets compute their prefix from their own location (wrong for a copy, and for the Python
# targets right only with python3-paraview installed, which conflicts with python3-vtk9 and so
# with libvtk9-dev); they check that every imported file exists (the pvpython and Python module
# files are in python3-paraview); and the modules' wrapping hierarchy files are in
# python3-paraview too. The copy fixes the prefix at /usr, skips the existence checks and finds
# the hierarchy files in DIR/usr, where step 1 extracted python3-paraview.
set -euo pipefail

if [[ $# -ne 1 || -z "$1" ]]; then
  echo "usage: $0 DIR   (DIR receives python3-paraview and the patched ParaView CMake package)" >&2
  exit 2
fi
root=$(cd "$(dirname "$0")/.." && pwd)
dir=$1
shipped=/usr/lib/x86_64-linux-gnu/cmake/paraview-5.11
export DEBIAN_FRONTEND=noninteractive

die() {
  echo "setup_paraview_dev.sh: $*" >&2
  exit 1
}

bash "$root/scripts/setup_paraview.sh" "$dir" >/dev/null

if [[ ! -f "$shipped/paraview-config.cmake" ]]; then
  [[ $(id -u) -eq 0 ]] || die "paraview-dev is missing; run as root or: apt-get install paraview-dev"
  apt-cache show paraview-dev >/dev/null 2>&1 || apt-get update -q >&2 || die "apt-get update failed"
  apt-get install -y -q --no-install-recommends paraview-dev >&2 ||
    die "apt-get install paraview-dev failed"
  [[ -f "$shipped/paraview-config.cmake" ]] || die "no $shipped/paraview-config.cmake after install"
fi

# mpirun for the plugin's parallel tests (mpirun -np 2 pvbatch).
if ! command -v mpirun >/dev/null 2>&1; then
  [[ $(id -u) -eq 0 ]] || die "mpirun is missing; run as root or: apt-get install openmpi-bin"
  apt-get install -y -q --no-install-recommends openmpi-bin >&2 || die "apt-get install openmpi-bin failed"
fi

extracted=$(cd "$dir/usr" && pwd)
copy="$dir/cmake/paraview-5.11"
stamp="$dir/cmake/.patched-from"
want="$(dpkg-query -W -f='${Version}' paraview-dev) $extracted $(sha256sum "$0" | cut -c1-16)"  # re-patched when this script changes
if [[ ! -f "$copy/paraview-config.cmake" || "$(cat "$stamp" 2>/dev/null)" != "$want" ]]; then
  rm -rf "$dir/cmake"
  mkdir -p "$dir/cmake.partial"
  cp -r "$shipped" "$dir/cmake.partial/paraview-5.11"
  (
    cd "$dir/cmake.partial/paraview-5.11"
    # Imported targets and VTK-m's package: prefix /usr wherever the copy lives; no check that
    # imported files exist.
    grep -rl --include='*.cmake' '_IMPORT_PREFIX STREQUAL "/"' . | while read -r f; do
      sed -i 's|^if(_IMPORT_PREFIX STREQUAL "/")|set(_IMPORT_PREFIX "/usr")\n&|' "$f"
    done
    grep -rl --include='*.cmake' 'get_filename_component(PACKAGE_PREFIX_DIR ' . | while read -r f; do
      sed -i 's|^get_filename_component(PACKAGE_PREFIX_DIR .*|set(PACKAGE_PREFIX_DIR "/usr")|' "$f"
    done
    grep -rl --include='*.cmake' 'if(NOT EXISTS "${_cmake_file}")' . | while read -r f; do
      sed -i 's|if(NOT EXISTS "${_cmake_file}")|if(FALSE)|' "$f"
    done
    # Module properties: headers under /usr would do, but hierarchy files are python3-paraview's.
    find . -name '*-vtk-module-properties.cmake' | while read -r f; do
      awk -v prefix="$extracted" '
        { lines[NR] = $0 }
        /^get_filename_component\(_vtk_module_import_prefix / { last = NR }
        END {
          for (i = 1; i <= NR; ++i) {
            print lines[i]
            if (i == last) print "set(_vtk_module_import_prefix \"" prefix "\")"
          }
        }' "$f" >"$f.new"
      mv "$f.new" "$f"
    done
  )
  mv "$dir/cmake.partial" "$dir/cmake"
  echo "$want" >"$stamp"
fi
echo "ParaView_DIR=$(cd "$copy" && pwd)"
