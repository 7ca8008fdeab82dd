#!/usr/bin/env bash
# `cmake --install` puts a working fluidviz on the PATH with its bash completion (issue 16).
#   install_and_complete.sh BUILD_DIR WORK_DIR
# Installs BUILD_DIR into WORK_DIR/prefix, runs the installed fluidviz from a PATH holding only
# its bin/ (and the system's), and completes with the installed completion script: the command
# names, run's options, lic's options and a --set key. It reads a legacy .vtk file, which needs
# the installed helper fluidviz-legacy-vtk-reader (libexec/fluidviz/).
set -euo pipefail
build=$1
work=$2
rm -rf "$work"
mkdir -p "$work"
cmake --install "$build" --prefix "$work/prefix" >"$work/install.log"
export PATH="$work/prefix/bin:/usr/bin:/bin"
cd "$work"  # away from the build tree: nothing of it is needed
version=$(fluidviz --version)
[[ $version =~ ^fluidviz\ [0-9]+\.[0-9]+\.[0-9]+\ \(commit\  ]] ||
  { echo "FAIL: fluidviz --version printed: $version"; exit 1; }
helper="$work/prefix/libexec/fluidviz/fluidviz-legacy-vtk-reader"
[[ -x $helper ]] || { echo "FAIL: no legacy VTK reader helper at $helper"; exit 1; }
{  # a solid-body rotation u = (-y, x) on 3 x 3 nodes: one centre, at the origin
  printf '# vtk DataFile Version 3.0\nrotation\nASCII\nDATASET STRUCTURED_POINTS\n'
  printf 'DIMENSIONS 3 3 1\nORIGIN -1 -1 0\nSPACING 1 1 1\nPOINT_DATA 9\nVECTORS velocity double\n'
  for y in -1 0 1; do for x in -1 0 1; do echo "$((-y)) $x 0"; done; done
} >rot.vtk
fluidviz topology rot.vtk -a velocity -o points.vtp --csv points.csv >topology.log ||
  { echo "FAIL: the installed fluidviz could not read rot.vtk:"; cat topology.log; exit 1; }
[[ $(sed -n 2p points.csv) == 0,0,0,centre,1,* ]] ||
  { echo "FAIL: rot.vtk's critical point is not the centre at 0,0,0:"; cat points.csv; exit 1; }
completion="$work/prefix/share/bash-completion/completions/fluidviz"
[[ -f $completion ]] || { echo "FAIL: no completion script at $completion"; exit 1; }
# shellcheck source=/dev/null
source "$completion"
complete_words() {  # the completions of the command line "$@" (the last word being typed)
  COMP_WORDS=("$@")
  COMP_CWORD=$((${#COMP_WORDS[@]} - 1))
  COMPREPLY=()
  _fluidviz
  printf '%s\n' "${COMPREPLY[@]}"
}
expect() {  # expect WORD COMMAND-LINE...: WORD is among the completions
  local word=$1
  shift
  local got
  got=$(complete_words "$@")  # not piped into grep -q: pipefail would see printf's SIGPIPE
  grep -qxF -- "$word" <<<"$got" ||
    { echo "FAIL: '$*' does not complete to '$word'; got: $(tr '\n' ' ' <<<"$got")"; exit 1; }
}
expect run fluidviz ru
expect topology fluidviz to
expect --replace fluidviz run scene.json --re
expect --resume fluidviz run scene.json --re
expect --array fluidviz lic field.vti --ar
echo "installed fluidviz: $version; reads legacy .vtk; completion of commands and options works"
