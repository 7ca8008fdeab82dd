#!/usr/bin/env bash
# Installs the Debian packages fluidviz builds with, when missing. Idempotent; silent when
# everything is present. Usage: scripts/setup.sh
set -euo pipefail

packages=(g++ cmake ninja-build pkg-config libvtk9-dev libosmesa6-dev libeigen3-dev libgtest-dev
          nlohmann-json3-dev libcli11-dev
          # the optional MPI build (FLUIDVIZ_MPI, issue 18): headers, mpicxx wrappers, mpirun
          libopenmpi-dev mpi-default-dev openmpi-bin
          # tests/integration: the grid-kinds generator uses VTK's numpy_support
          python3-numpy
          # movies of picture frames (output.images[].movie, output.lic[].movie), ffprobe in tests
          ffmpeg
          # scripts/sanitize.sh: clang with ASan/UBSan/libFuzzer runtimes, its OpenMP, symbolizer
          clang-14 libclang-rt-14-dev libomp-14-dev llvm-14)

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done
[[ ${#missing[@]} -eq 0 ]] && exit 0

sudo=""
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "setup: need root (or sudo) to install: ${missing[*]}" >&2; exit 1; }
  sudo="sudo"
fi

# Debian's python3-paraview conflicts with python3-vtk9, which libvtk9-dev needs. fluidviz uses a
# private copy of python3-paraview for its ParaView tests (scripts/setup_paraview.sh), so the
# system one has to make way for the VTK headers.
if dpkg-query -W -f='${Status}' python3-paraview 2>/dev/null | grep -q "install ok installed"; then
  echo "setup: removing python3-paraview (conflicts with libvtk9-dev; the tests use a private copy)" >&2
  $sudo env DEBIAN_FRONTEND=noninteractive apt-get remove -y -qq python3-paraview >/dev/null
fi

echo "setup: installing ${missing[*]}" >&2
$sudo apt-get update -qq
$sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq \
  "${missing[@]}" >/dev/null
echo "setup: done" >&2
