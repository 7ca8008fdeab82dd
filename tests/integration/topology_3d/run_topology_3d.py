"""`fluidviz topology` on a 3D .vti without --slice, end to end (issue 21).

    run_topology_3d.py FLUIDVIZ OUT_DIR

Writes the ABC flow v = (A sin z + C cos y, B sin x + A cos z, C sin y + B cos x), A = 1, B = 0.9,
C = 0.8 (Dombre et al., J. Fluid Mech. 167, 1986) on 33^3 nodes covering [-0.1, 2 pi - 0.1]^3 as
OUT_DIR/abc.vti (Debian's python3-vtk9), runs `fluidviz topology abc.vti -a velocity -o
points.vtp --csv points.csv` and checks: exit 0; eight points, four saddle_1 of index +1 and four
saddle_2 of index -1 (the flow is divergence-free, the eigenvalues of every stagnation point add
up to 0); each within 0.05 cells of a stagnation point of the analytic field (Newton from it,
|v| < 1e-12; the piecewise-linear interpolant's zeros are O(h^2) off: measured 0.026 cells); a
separatrices file. pvbatch then opens points.vtp and
points_separatrices.vtp (tests/CMakeLists.txt). Exit 0 when all pass, 3 on a failed check.
"""
import math
import os
import subprocess
import sys

A, B, C = 1.0, 0.9, 0.8
N = 33
LO = -0.1
H = 2 * math.pi / (N - 1)
TOLERANCE_CELLS = 0.05


def velocity(x, y, z):
    return (A * math.sin(z) + C * math.cos(y), B * math.sin(x) + A * math.cos(z),
            C * math.sin(y) + B * math.cos(x))


def jacobian(x, y, z):
    return [[0.0, -C * math.sin(y), A * math.cos(z)],
            [B * math.cos(x), 0.0, -A * math.sin(z)],
            [-B * math.sin(x), C * math.cos(y), 0.0]]


def solve3(m, r):
    def det(a):
        return (a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
                a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]))
    d = det(m)
    out = []
    for c in range(3):
        mc = [[r[i] if j == c else m[i][j] for j in range(3)] for i in range(3)]
        out.append(det(mc) / d)
    return out


def write_vti(path):
    from vtkmodules.vtkCommonCore import vtkDoubleArray
    from vtkmodules.vtkCommonDataModel import vtkImageData
    from vtkmodules.vtkIOXML import vtkXMLImageDataWriter
    image = vtkImageData()
    image.SetDimensions(N, N, N)
    image.SetOrigin(LO, LO, LO)
    image.SetSpacing(H, H, H)
    v = vtkDoubleArray()
    v.SetName("velocity")
    v.SetNumberOfComponents(3)
    for k in range(N):
        for j in range(N):
            for i in range(N):
                v.InsertNextTuple3(*velocity(LO + i * H, LO + j * H, LO + k * H))
    image.GetPointData().AddArray(v)
    writer = vtkXMLImageDataWriter()
    writer.SetFileName(path)
    writer.SetInputData(image)
    if writer.Write() != 1:
        raise RuntimeError("could not write " + path)


def main():
    fluidviz, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)
    vti = os.path.join(out, "abc.vti")
    write_vti(vti)
    points, csv = os.path.join(out, "points.vtp"), os.path.join(out, "points.csv")
    run = subprocess.run([fluidviz, "topology", vti, "-a", "velocity", "-o", points, "--csv", csv],
                         capture_output=True, text=True)
    print(run.stdout, end="")
    failures = []
    if run.returncode != 0:
        failures.append("fluidviz topology exited %d: %s" % (run.returncode, run.stderr))
    for f in (points, csv, os.path.join(out, "points_separatrices.vtp")):
        if not os.path.isfile(f):
            failures.append("no " + f)
    rows = []
    if os.path.isfile(csv):
        with open(csv) as f:
            header = f.readline().strip().split(",")
            rows = [dict(zip(header, line.strip().split(","))) for line in f]
    kinds = sorted((r["type"], int(r["index"])) for r in rows)
    if kinds != [("saddle_1", 1)] * 4 + [("saddle_2", -1)] * 4:
        failures.append("points %s, expected four saddle_1 (+1) and four saddle_2 (-1)" % kinds)
    worst = 0.0
    for r in rows:
        p = [float(r["x"]), float(r["y"]), float(r["z"])]
        q = list(p)
        for _ in range(30):
            step = solve3(jacobian(*q), velocity(*q))
            q = [q[i] - step[i] for i in range(3)]
        if math.sqrt(sum(c * c for c in velocity(*q))) > 1e-12:
            failures.append("Newton from %s did not converge" % p)
            continue
        worst = max(worst, max(abs(p[i] - q[i]) for i in range(3)) / H)
    if worst > TOLERANCE_CELLS:
        failures.append("a point is %.3g cells from the analytic one (tolerance %g)"
                        % (worst, TOLERANCE_CELLS))
    print("topology_3d: %d points, largest distance to the analytic points %.3g cells"
          % (len(rows), worst))
    for f in failures:
        print("topology_3d: FAIL: " + f, flush=True)
    return 3 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
