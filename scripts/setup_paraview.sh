#!/usr/bin/env bash
# Makes ParaView's pvbatch usable for fluidviz's integration tests. Idempotent.
#
#   scripts/setup_paraview.sh DIR
#
# 1. Installs Debian's `paraview` (pvbatch) with apt-get if pvbatch is missing.
# 2. Extracts `python3-paraview` (the paraview.simple Python modules) into DIR, in the version of
#    the installed paraview. It is extracted, not installed, because the package conflicts with
#    python3-vtk9, which libvtk9-dev needs.
# 3. Writes DIR/paraview.env (one line, PYTHONPATH=...) and prints that line last on stdout.
#
# Use:  PYTHONPATH=DIR/usr/lib/python3/dist-packages pvbatch tests/integration/pvbatch_check.py ...
# (tests/CMakeLists.txt runs this script as the ctest fixture `paraview`, DIR = build/paraview-python.)
# When everything is already there it prints only the PYTHONPATH line. apt's output goes to stderr.
set -euo pipefail

if [[ $# -ne 1 ]]; then
  echo "usage: $0 DIR   (DIR receives the extracted python3-paraview)" >&2
  exit 2
fi
dir=$1
[[ -n "$dir" ]] || { echo "setup_paraview.sh: DIR is empty" >&2; exit 2; }
site_packages="$dir/usr/lib/python3/dist-packages"
version_stamp="$dir/.python3-paraview-version"
export DEBIAN_FRONTEND=noninteractive

die() {
  echo "setup_paraview.sh: $*" >&2
  exit 1
}

require_root_for() {
  [[ $(id -u) -eq 0 ]] || die "$1 needs root (apt-get); run as root or install it: apt-get install $2"
}

# apt-get works from package lists; a fresh machine may have none yet.
apt_knows() {
  apt-cache show "$1" >/dev/null 2>&1
}

update_lists_unless_known() {
  apt_knows "$1" || apt-get update -q >&2 || die "apt-get update failed"
  apt_knows "$1" || die "apt knows no package '$1'"
}

install_pvbatch_if_missing() {
  command -v pvbatch >/dev/null 2>&1 && return 0
  require_root_for pvbatch paraview
  update_lists_unless_known paraview
  apt-get install -y -q --no-install-recommends paraview >&2 || die "apt-get install paraview failed"
  command -v pvbatch >/dev/null 2>&1 || die "pvbatch is still missing after installing paraview"
}

installed_paraview_version() {
  dpkg-query -W -f='${Version}' paraview 2>/dev/null ||
    die "pvbatch is present but the Debian package paraview is not; install python3-paraview's" \
        "modules by hand and set PYTHONPATH"
}

download=""
trap '[[ -z "$download" ]] || rm -rf "$download"' EXIT

extract_python_modules() {
  local version=$1
  update_lists_unless_known python3-paraview
  # apt's _apt sandbox user must be able to write the download folder.
  download=$(mktemp -d)
  chmod 777 "$download"
  (cd "$download" && apt-get download -q "python3-paraview=$version" >&2) ||
    die "apt-get download python3-paraview=$version failed"
  # Extract beside DIR's final content and move into place, so an interrupted run leaves no
  # half-extracted tree that a later run would take as complete.
  mkdir -p "$dir"
  # DIR/usr is replaced only if this script made it (the stamp says so): DIR=/ must not cost /usr.
  if [[ -e "$dir/usr" && ! -f "$version_stamp" ]]; then
    die "$dir/usr exists but was not extracted by this script; give an empty or new DIR"
  fi
  rm -rf "${dir:?}/.extracting" "${dir:?}/usr"
  dpkg-deb -x "$download"/python3-paraview_*.deb "$dir/.extracting" || die "dpkg-deb -x failed"
  mv "$dir/.extracting/usr" "$dir/usr"
  rm -rf "$dir/.extracting"
  echo "$version" >"$version_stamp"
}

install_pvbatch_if_missing
version=$(installed_paraview_version)
if [[ ! -f "$site_packages/paraview/simple.py" || "$(cat "$version_stamp" 2>/dev/null)" != "$version" ]]; then
  require_root_for python3-paraview python3-paraview
  extract_python_modules "$version"
fi
[[ -f "$site_packages/paraview/simple.py" ]] || die "no paraview/simple.py under $site_packages"

pythonpath=$(cd "$site_packages" && pwd)
echo "PYTHONPATH=$pythonpath" >"$dir/paraview.env"
echo "PYTHONPATH=$pythonpath"
