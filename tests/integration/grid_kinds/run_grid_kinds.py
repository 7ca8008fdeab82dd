"""Every input kind through every field command (issue 15's acceptance test, part 1).

    run_grid_kinds.py FLUIDVIZ OUT_DIR

Writes the analytic field of make_grid_kinds.py as every kind fluidviz reads (.vti point and cell
data, .vtr, .vts, .vtu, .vtp, .pvti, .pvtu, .vtm, legacy .vtk) into OUT_DIR/inputs, runs
`fluidviz lic`, `streamlines`, `topology` and `isosurface` on each (non-images resampled with
--spacing 0.0625, the nodes' own spacing) into OUT_DIR/<kind>/, and checks:
  - every command exits 0 and writes its outputs;
  - topology finds one centre within 0.05 cells of the analytic (XC, YC);
  - the isosurface s = 0.1225 (a cylinder of radius 0.35, height 0.1875: area 0.41233) has the
    area of the point-data .vti within 1% for every kind, and that one is within 1% of the
    analytic area (marching cubes on the 1/16 grid). 1%: the cell-data .vti's nodes average s
    over the 8 cells around them, which adds h^2/2 = 0.00195 to s and shrinks the radius by
    0.8%;
  - every PNG is a PNG of the same size as the point-data .vti's.
The .vtp/.vti outputs are then opened by pvbatch (tests/CMakeLists.txt, pvbatch_check.py).
Prints one line per kind; exit 0 when all pass, 3 on a failed check.
"""
import math
import os
import re
import struct
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import make_grid_kinds as field  # noqa: E402

KINDS = ["points.vti", "cells.vti", "grid.vtr", "grid.vts", "grid.vtu", "layers.vtp",
         "pieces.pvti", "pieces.pvtu", "blocks.vtm", "legacy.vtk"]
REFERENCE = "points.vti"
ISO_VALUE = 0.1225
ANALYTIC_AREA = 2 * math.pi * math.sqrt(ISO_VALUE) * (field.N[2] - 1) * field.H
AREA_TOLERANCE = 0.01
CENTRE_TOLERANCE_CELLS = 0.05
SPACING = ["--spacing", str(field.H)]

failures = []


def fail(kind, message):
    failures.append("%s: %s" % (kind, message))


def run(fluidviz, kind, args):
    result = subprocess.run([fluidviz] + args, capture_output=True, text=True)
    if result.returncode != 0:
        fail(kind, "fluidviz %s exited %d: %s" % (args[0], result.returncode, result.stderr.strip()))
    return result.stdout


def png_size(path):
    with open(path, "rb") as f:
        head = f.read(24)
    if len(head) < 24 or head[:8] != b"\x89PNG\r\n\x1a\n":
        return None
    return struct.unpack(">II", head[16:24])


def centres(csv_path):
    rows = []
    with open(csv_path) as f:
        header = f.readline().strip().split(",")
        for line in f:
            row = dict(zip(header, line.strip().split(",")))
            rows.append((row["type"], float(row["x"]), float(row["y"])))
    return rows


def run_kind(fluidviz, inputs, out, kind):
    path = os.path.join(inputs, kind)
    folder = os.path.join(out, kind.replace(".", "_"))
    os.makedirs(folder, exist_ok=True)
    o = lambda name: os.path.join(folder, name)
    flow = ["-a", "v", "--slice", "z=0"] + SPACING
    run(fluidviz, kind, ["lic", path] + flow + ["--resolution", "200", "-o", o("lic.png"),
                                                "--vti", o("lic.vti")])
    run(fluidviz, kind, ["streamlines", path] + flow + ["--width", "200", "-o", o("lines.vtp"),
                                                        "--png", o("lines.png")])
    run(fluidviz, kind, ["topology", path] + flow + ["--width", "200", "-o", o("points.vtp"),
                                                     "--csv", o("points.csv"),
                                                     "--png", o("points.png")])
    iso = run(fluidviz, kind, ["isosurface", path, "-a", "s", "--value", str(ISO_VALUE)] +
              SPACING + ["-o", o("iso.vtp")])
    area = re.search(r"area ([0-9.eE+-]+)", iso)
    result = {"area": float(area.group(1)) if area else None, "png": {}}
    for name in ("lic.vti", "lines.vtp", "points.vtp", "iso.vtp"):
        if not os.path.isfile(o(name)):
            fail(kind, "no %s written" % name)
    for name in ("lic.png", "lines.png", "points.png"):
        result["png"][name] = png_size(o(name)) if os.path.isfile(o(name)) else None
        if result["png"][name] is None:
            fail(kind, "%s is missing or not a PNG" % name)
    if os.path.isfile(o("points.csv")):
        found = centres(o("points.csv"))
        cells = [math.hypot(x - field.XC, y - field.YC) / field.H for t, x, y in found]
        if len(found) != 1 or found[0][0] != "centre" or cells[0] > CENTRE_TOLERANCE_CELLS:
            fail(kind, "critical points %s, expected one centre within %g cells of (%g, %g)"
                 % (found, CENTRE_TOLERANCE_CELLS, field.XC, field.YC))
        result["centre_error_cells"] = cells[0] if cells else None
    return result


def main():
    fluidviz, out = sys.argv[1], sys.argv[2]
    inputs = os.path.join(out, "inputs")
    sys.argv = [sys.argv[0], inputs]
    field.main()
    results = {kind: run_kind(fluidviz, inputs, out, kind) for kind in KINDS}
    reference = results[REFERENCE]
    if reference["area"] is None or abs(reference["area"] / ANALYTIC_AREA - 1) > AREA_TOLERANCE:
        fail(REFERENCE, "isosurface area %s, analytic %.6g (tolerance %g)"
             % (reference["area"], ANALYTIC_AREA, AREA_TOLERANCE))
    for kind, r in results.items():
        if r["area"] is None or reference["area"] is None or \
                abs(r["area"] / reference["area"] - 1) > AREA_TOLERANCE:
            fail(kind, "isosurface area %s, %s has %s (tolerance %g)"
                 % (r["area"], REFERENCE, reference["area"], AREA_TOLERANCE))
        for name, size in r["png"].items():
            if size != reference["png"][name]:
                fail(kind, "%s is %s px, %s's is %s" % (name, size, REFERENCE,
                                                        reference["png"][name]))
        print("%-12s area %s  centre off by %s cells  pngs %s"
              % (kind, r["area"], r.get("centre_error_cells"), r["png"]), flush=True)
    for f in failures:
        print("grid_kinds: FAIL: " + f, flush=True)
    return 3 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
