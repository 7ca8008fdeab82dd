#!/usr/bin/env bash
# The plugin links ParaView's VTK only (issue 17): no library of Debian's VTK 9.1 (libvtk*-9.1)
# in `ldd` of the plugin and its module library, and ParaView's own (libvtk*-pv5.11) present, so
# that the check cannot pass on a file that links nothing.
#   check_links.sh PLUGIN.so
set -euo pipefail
plugin=$1
status=0
for lib in "$plugin" "$(dirname "$plugin")/libFluidvizFilters.so"; do
  [[ -f "$lib" ]] || { echo "FAIL: $lib is missing" >&2; exit 1; }
  deps=$(ldd "$lib")
  if grep -E 'libvtk[^ ]*-9\.1' <<<"$deps"; then
    echo "FAIL: $lib links Debian's VTK 9.1 (above)" >&2
    status=1
  fi
  pv=$(grep -cE 'libvtk[^ ]*-pv5\.11' <<<"$deps" || true)
  [[ $pv -gt 0 ]] || { echo "FAIL: $lib links no ParaView 5.11 library" >&2; status=1; }
  if grep -q 'not found' <<<"$deps"; then
    grep 'not found' <<<"$deps" >&2
    echo "FAIL: $lib has unresolved libraries" >&2
    status=1
  fi
  echo "$(basename "$lib"): $pv ParaView 5.11 libraries, none of VTK 9.1"
done
exit $status
