#!/usr/bin/env bash
# The installed CMake package (issue 17): a project of its own, examples/consumer, finds fluidviz
# with find_package(fluidviz CONFIG REQUIRED COMPONENTS vtk) in an installed prefix, builds and
# runs. Checks:
#   - the package files: fluidvizConfig.cmake, its version file, the two target sets;
#   - no file of the installed tree holds a path of the source checkout (which holds the build
#     tree): no include directory, library path or __FILE__ of this checkout;
#   - taylor_green_core (VTK-free targets only) passes its checks against the exact Taylor-Green
#     decay and critical points, and links no VTK library (ldd);
#   - taylor_green_vti (COMPONENTS vtk) writes and reads back a .vti bit-equal.
#   consumer.sh SOURCE_DIR BUILD_DIR WORK_DIR
set -euo pipefail
source_dir=$1
build=$2
work=$3
rm -rf "$work"
mkdir -p "$work"
prefix="$work/prefix"
cmake --install "$build" --prefix "$prefix" >"$work/install.log"
package="$prefix/lib/cmake/fluidviz"
for f in fluidvizConfig.cmake fluidvizConfigVersion.cmake fluidvizCoreTargets.cmake \
         fluidvizVtkTargets.cmake; do
  [[ -f $package/$f ]] || { echo "FAIL: the package has no $f in $package"; exit 1; }
done
leaks=$(grep -rlF -- "$source_dir" "$prefix" || true)
[[ -z $leaks ]] || { echo "FAIL: installed files name the checkout $source_dir:"; echo "$leaks"; exit 1; }
# The consumer is copied away from the checkout: it sees the installed prefix only.
cp -r "$source_dir/examples/consumer" "$work/consumer"
cmake -S "$work/consumer" -B "$work/consumer-build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix" >"$work/configure.log" 2>&1 ||
  { echo "FAIL: the consumer does not configure:"; cat "$work/configure.log"; exit 1; }
cmake --build "$work/consumer-build" >"$work/build.log" 2>&1 ||
  { echo "FAIL: the consumer does not build:"; cat "$work/build.log"; exit 1; }
cd "$work"
core="$work/consumer-build/taylor_green_core"
"$core" || { echo "FAIL: taylor_green_core's checks failed"; exit 1; }
if ldd "$core" | grep -q 'libvtk'; then
  echo "FAIL: taylor_green_core (VTK-free targets) links VTK:"; ldd "$core" | grep libvtk; exit 1
fi
"$work/consumer-build/taylor_green_vti" "$work/tg.vti" ||
  { echo "FAIL: taylor_green_vti's round trip failed"; exit 1; }
echo "the installed package builds examples/consumer; both programs pass; no checkout path installed"
