"""pvbatch checks of the fluidviz ParaView plugin (paraview/, issue 17), on a snapshot of the
default scene (the four-roll mill) written by `fluidviz run`.

  pvbatch plugin_checks.py serial   --plugin SO --fluidviz BIN --input SNAPSHOT.vti --work DIR
  mpirun -np 2 pvbatch plugin_checks.py parallel --plugin SO --fluidviz BIN --input ... --work ...
  pvbatch plugin_checks.py bad-property --plugin SO --input SNAPSHOT.vti
  pvbatch plugin_checks.py example --plugin SO --fluidviz BIN --input SNAPSHOT.vti --work TEX.vti

serial: the proxies FluidvizLIC (its texture, and lic_color: the texture blended with the
  snapshot's density as the CLI's picture shows it, pixel for pixel), FluidvizCriticalPoints and
  FluidvizStreamlines (a seed lattice and evenly spaced lines), with non-default properties, give the arrays `fluidviz lic --vti`,
  `fluidviz topology` and `fluidviz streamlines` write for the same settings, bit for bit
  (texture, mask, every critical-point, separatrix and streamline array and point); the snapshot
  must have masked nodes (the rollers), so that the plugin is seen to mask what the CLI masks.
  FluidvizResample on a patch of SPH particles written here gives the grid of `fluidviz
  resample`, every array bit for bit.
parallel: under 2 MPI ranks the reader is split into 2 pieces; the LIC pieces of the ranks are
  the CLI texture pixel for pixel and tile it, and the critical points of the ranks together are
  the CLI's points, each found on exactly one rank, with their separatrices whole; the
  streamlines of the ranks together are the CLI's, each line on one rank and whole; the
  resampled pieces are blocks of the CLI grid, node for node.
example: TEX.vti, written by examples/paraview/lic_in_pvpython.py from SNAPSHOT.vti, is the
  texture of `fluidviz lic --vti` with the same (default) settings.
bad-property: a property outside its declared range fails the update with the property, the
  scene key and the range (ctest matches the message); streamline properties that contradict
  each other (rk45 with min_step > max_step) give no lines.
Exits non-zero with the first difference.
"""
import argparse
import os
import re
import subprocess
import sys

import numpy as np
from paraview import servermanager as sm
from paraview.simple import LoadPlugin, XMLImageDataReader, XMLPolyDataReader
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkIOXML import vtkXMLImageDataReader, vtkXMLPolyDataReader, vtkXMLPolyDataWriter
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkIdList, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData

LIC_SETTINGS = {"Width": 240, "Height": 240, "Length": 15.0, "Kernel": "hann", "NoiseSeed": 3}
LIC_FLAGS = ["--resolution", "240x240", "--length", "15", "--kernel", "hann", "--seed", "3"]
# The texture blended with a point scalar of the snapshot (not speed: the array path), on a
# non-default map and weight, over a range inside the scalar's (so that both ends clamp). The
# range is written with few digits, so that the CLI and the proxy parse the same doubles.
BLEND_SCALAR = "density"
BLEND_SETTINGS = {"ColorBy": BLEND_SCALAR, "LicWeight": 0.4, "Colormap": "inferno"}
BLEND_FLAGS = ["--color-by", BLEND_SCALAR, "--weight", "0.4", "--colormap", "inferno"]


def blend_range(input_path):
    """The 10th and 90th percentiles of the blend scalar's finite values, to 6 digits."""
    data = values(read_image(input_path).GetPointData().GetArray(BLEND_SCALAR))
    lo, hi = np.percentile(data[np.isfinite(data)], [10, 90])
    return float("%.6g" % lo), float("%.6g" % hi)
TOPOLOGY_SETTINGS = {"ClusterRadius": 2.0}
TOPOLOGY_FLAGS = ["--set", "cluster_radius=2"]
# Two seedings: a lattice (array property SeedingGridCounts, non-default integration) and evenly
# spaced lines (each placed after the ones before it: the case where a rank cannot trace its
# own seeds alone).
STREAMLINE_CASES = {
    "grid": ({"SeedingGridCounts": [12, 9, 1], "IntegrationStep": 0.5,
              "IntegrationMaxLength": 400.0},
             ["--seeds", "grid:12,9", "--step", "0.5", "--max-length", "400"]),
    "evenly spaced": ({"SeedingStrategy": "evenly_spaced",
                       "SeedingEvenlySpacedSeparatingDistance": 6.0},
                      ["--evenly-spaced", "6"]),
}


def fail(message):
    print("FAIL: " + message, file=sys.stderr)
    sys.exit(1)


def run(command):
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        fail("%s exited %d:\n%s" % (" ".join(command), done.returncode, done.stderr))
    return done.stdout


# The CLI's files are read here, in this process, not through proxies: under MPI a reader proxy
# is split into pieces, and Fetch appends image pieces only where they are poly data.
def read_image(path):
    reader = vtkXMLImageDataReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def read_poly(path):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def values(array):
    if array.IsA("vtkStringArray"):
        return np.array([array.GetValue(i) for i in range(array.GetNumberOfValues())])
    return vtk_to_numpy(array)


def picture_texture(png, stdout, texture):
    """The texture's pixels of the CLI picture `png` as an RGB point array lic_color on the
    texture's nodes (row 0 = lowest y): the CLI says where it drew the texture ("texture W x H px
    at picture pixels x [l, r), y [t, b)", y counted down from the top row)."""
    m = re.search(r"at picture pixels x \[(\d+), (\d+)\), y \[(\d+), (\d+)\)", stdout)
    if not m:
        fail("fluidviz lic did not say where it drew the texture:\n" + stdout)
    left, right, top, bottom = map(int, m.groups())
    reader = vtkPNGReader()
    reader.SetFileName(png)
    reader.Update()
    picture = reader.GetOutput()
    width, height = picture.GetDimensions()[:2]
    rgb = values(picture.GetPointData().GetScalars()).reshape(height, width, -1)[:, :, :3]
    nx, ny = texture.GetDimensions()[:2]
    if (right - left, bottom - top) != (nx, ny):
        fail("the CLI picture's texture is %d x %d px, its texture %d x %d" % (
            right - left, bottom - top, nx, ny))
    # vtkPNGReader's row 0 is the picture's bottom row.
    block = rgb[height - bottom:height - top, left:right, :]
    array = numpy_to_vtk(np.ascontiguousarray(block.reshape(-1, 3)), deep=1)
    array.SetName("lic_color")
    texture.GetPointData().AddArray(array)


def cli_outputs(args):
    texture = os.path.join(args.work, "cli_lic.vti")
    png = os.path.join(args.work, "cli_lic.png")
    lo, hi = blend_range(args.input)
    stdout = run([args.fluidviz, "lic", args.input, "-a", "velocity", "-o", png, "--vti",
                  texture, "--range", "%.6g,%.6g" % (lo, hi)] + LIC_FLAGS + BLEND_FLAGS)
    image = read_image(texture)
    picture_texture(png, stdout, image)
    points = os.path.join(args.work, "cli_points.vtp")
    separatrices = os.path.join(args.work, "cli_separatrices.vtp")
    run([args.fluidviz, "topology", args.input, "-a", "velocity", "-o", points,
         "--separatrices", separatrices] + TOPOLOGY_FLAGS)
    return image, read_poly(points), read_poly(separatrices)


def cli_streamlines(args):
    lines = {}
    for name, (_, flags) in STREAMLINE_CASES.items():
        path = os.path.join(args.work, "cli_streamlines_%s.vtp" % name.replace(" ", "_"))
        run([args.fluidviz, "streamlines", args.input, "-a", "velocity", "-o", path] + flags)
        lines[name] = read_poly(path)
    return lines


# Resampling: non-default kernel and grid spacing; h from the particles' array smoothing_length
# (no SmoothingLength given), as the CLI takes it.
RESAMPLE_SETTINGS = {"Kernel": "wendland_c2", "SetSpacing": 1, "Spacing": 0.004}
RESAMPLE_FLAGS = ["--kernel", "wendland_c2", "--spacing", "0.004"]


def write_particles(path):
    """A patch of 24 x 16 SPH particles, 0.01 m apart, displaced off the lattice by a smooth
    field (so that sums are not symmetric), in a rotating flow: velocity (3), pressure,
    mass, density and smoothing_length, as an SPH snapshot has them."""
    i, j = np.meshgrid(np.arange(24), np.arange(16), indexing="xy")
    x = 0.01 * i + 0.002 * np.sin(1.7 * i + 0.9 * j)
    y = 0.01 * j + 0.002 * np.cos(1.1 * i - 1.3 * j)
    x, y = x.ravel(), y.ravel()
    data = vtkPolyData()
    points = vtkPoints()
    points.SetData(numpy_to_vtk(np.column_stack([x, y, np.zeros_like(x)]), deep=True))
    data.SetPoints(points)
    density = 1000.0 * (1 + 0.01 * np.sin(40 * x))
    columns = {"velocity": np.column_stack([-(y - 0.08), x - 0.12, np.zeros_like(x)]),
               "pressure": 9.81 * density * (0.16 - y), "density": density,
               "mass": np.full_like(x, 1000.0 * 0.01 ** 2),
               "smoothing_length": np.full_like(x, 1.3 * 0.01)}
    for name, column in columns.items():
        array = numpy_to_vtk(np.ascontiguousarray(column), deep=True)
        array.SetName(name)
        data.GetPointData().AddArray(array)
    writer = vtkXMLPolyDataWriter()
    writer.SetFileName(path)
    writer.SetInputData(data)
    if not writer.Write():
        fail("cannot write %s" % path)


def cli_resampled(args):
    particles = os.path.join(args.work, "particles.vtp")
    grid = os.path.join(args.work, "cli_grid.vti")
    write_particles(particles)
    run([args.fluidviz, "resample", particles, "-o", grid] + RESAMPLE_FLAGS)
    return particles, read_image(grid)


def resample_proxy(particles):
    reader = XMLPolyDataReader(FileName=particles)
    return FluidvizResample(Input=reader, **RESAMPLE_SETTINGS)


def check_same_grid(what, got, expected, extent, geometry_tolerance=0.0):
    """`got` holds the nodes `extent` of the CLI grid `expected`: every point array of the CLI
    (NaN where unsupported, in the same bits), origin and spacing as check_same_texture."""
    e = expected.GetExtent()
    nx, ny = e[1] - e[0] + 1, e[3] - e[2] + 1
    names = array_names(expected.GetPointData())
    if sorted(array_names(got.GetPointData())) != sorted(names):
        fail("%s: arrays %s, the CLI's %s" % (what, array_names(got.GetPointData()), names))
    for name in names:
        full = values(expected.GetPointData().GetArray(name))
        full = full.reshape((-1, ny, nx) + full.shape[1:])
        piece = full[extent[4]:extent[5] + 1, extent[2]:extent[3] + 1, extent[0]:extent[1] + 1]
        g = values(got.GetPointData().GetArray(name))
        if g.dtype != piece.dtype or not np.array_equal(
                g.reshape(-1).view(np.uint8), np.ascontiguousarray(piece).reshape(-1).view(np.uint8)):
            fail("%s: %s differs from the CLI's on extent %s" % (what, name, extent))
    for a in range(3):
        size = abs(expected.GetOrigin()[a]) + expected.GetSpacing()[a] * (e[2 * a + 1] - e[2 * a])
        if abs(got.GetOrigin()[a] - expected.GetOrigin()[a]) > geometry_tolerance * size or \
                not np.isclose(got.GetSpacing()[a], expected.GetSpacing()[a],
                               rtol=geometry_tolerance, atol=0):
            fail("%s: origin/spacing %s %s, CLI %s %s" % (what, got.GetOrigin(), got.GetSpacing(),
                                                          expected.GetOrigin(),
                                                          expected.GetSpacing()))


def unsupported_nodes(grid):
    return int((values(grid.GetPointData().GetArray("vtkValidPointMask")) == 0).sum())


def plugin_proxies(input_path):
    reader = XMLImageDataReader(FileName=input_path)
    reader.UpdatePipeline()
    lo, hi = blend_range(input_path)
    lic = FluidvizLIC(Input=reader, InputVectors=["POINTS", "velocity"], SetRangeMin=1,
                      RangeMin=lo, SetRangeMax=1, RangeMax=hi, **LIC_SETTINGS, **BLEND_SETTINGS)
    topology = FluidvizCriticalPoints(Input=reader, InputVectors=["POINTS", "velocity"],
                                      **TOPOLOGY_SETTINGS)
    streamlines = {name: FluidvizStreamlines(Input=reader, InputVectors=["POINTS", "velocity"],
                                             **settings)
                   for name, (settings, _) in STREAMLINE_CASES.items()}
    return lic, topology, streamlines


def same_arrays(what, got, expected, names):
    for name in names:
        g, e = got.GetAbstractArray(name), expected.GetAbstractArray(name)
        if g is None:
            fail("%s: the plugin's output has no array %s" % (what, name))
        if not np.array_equal(values(g), values(e)):
            fail("%s: array %s differs (plugin %s, CLI %s)" % (what, name, values(g)[:5],
                                                               values(e)[:5]))


def array_names(data):
    return [data.GetAbstractArray(i).GetName() for i in range(data.GetNumberOfArrays())]


def check_same_texture(what, got, expected, extent, geometry_tolerance=0.0):
    """`got` holds the pixels `extent` of the CLI texture `expected`. Spacing within
    `geometry_tolerance` (relative) and origin within `geometry_tolerance` of the texture's size:
    moving image data between MPI ranks rounds the position of a piece's first pixel (not the
    origin) to 6 significant digits; the pixel values are moved exactly."""
    e = expected.GetExtent()
    nx = e[1] - e[0] + 1
    for name in ("lic", "lic_mask", "lic_color"):
        if expected.GetPointData().GetArray(name) is None:
            continue  # lic_color: only where the CLI drew a blended picture
        full = values(expected.GetPointData().GetArray(name))
        full = full.reshape((-1, nx) + full.shape[1:])
        piece = full[extent[2]:extent[3] + 1, extent[0]:extent[1] + 1].reshape(
            (-1,) + full.shape[2:])
        if got.GetPointData().GetArray(name) is None:
            fail("%s: the plugin's output has no array %s" % (what, name))
        if not np.array_equal(values(got.GetPointData().GetArray(name)), piece):
            differ = values(got.GetPointData().GetArray(name)) != piece
            fail("%s: %s differs from the CLI's on extent %s (%d values)" % (
                what, name, extent, int(differ.sum())))
    for a in range(3):
        size = abs(expected.GetOrigin()[a]) + expected.GetSpacing()[a] * (e[2 * a + 1] - e[2 * a])
        if abs(got.GetOrigin()[a] - expected.GetOrigin()[a]) > geometry_tolerance * size or \
                not np.isclose(got.GetSpacing()[a], expected.GetSpacing()[a],
                               rtol=geometry_tolerance, atol=0):
            fail("%s: origin/spacing %s %s, CLI %s %s" % (what, got.GetOrigin(), got.GetSpacing(),
                                                          expected.GetOrigin(),
                                                          expected.GetSpacing()))


def check_same_points(what, got, expected):
    n = expected.GetNumberOfPoints()
    if got.GetNumberOfPoints() != n:
        fail("%s: %d critical points, the CLI %d" % (what, got.GetNumberOfPoints(), n))
    if not np.array_equal(vtk_to_numpy(got.GetPoints().GetData()),
                          vtk_to_numpy(expected.GetPoints().GetData())):
        fail("%s: critical point positions differ" % what)
    same_arrays(what, got.GetPointData(), expected.GetPointData(),
                array_names(expected.GetPointData()))


def separatrix_lines(data):
    """Each polyline as (cell arrays..., its points as a tuple), in a canonical order."""
    cells = data.GetCellData()
    names = sorted(array_names(cells))  # appending pieces may reorder the arrays
    columns = [values(cells.GetAbstractArray(name)) for name in names]
    lines = []
    ids = data.GetLines()
    ids.InitTraversal()
    cell = vtkIdList()
    k = 0
    while ids.GetNextCell(cell):
        pts = tuple(data.GetPoint(cell.GetId(i)) for i in range(cell.GetNumberOfIds()))
        lines.append((tuple(c[k] for c in columns), pts))
        k += 1
    return sorted(lines)


def streamline_lines(data):
    """Each polyline as (its cell arrays, its points, its point arrays), sorted: the lines of
    all ranks, appended in any order, compare with the serial ones."""
    cells, pointData = data.GetCellData(), data.GetPointData()
    cell_columns = [values(cells.GetAbstractArray(n)) for n in sorted(array_names(cells))]
    point_columns = [values(pointData.GetAbstractArray(n)) for n in sorted(array_names(pointData))]
    lines = []
    ids = data.GetLines()
    ids.InitTraversal()
    cell = vtkIdList()
    k = 0
    while ids.GetNextCell(cell):
        at = [cell.GetId(i) for i in range(cell.GetNumberOfIds())]
        lines.append((tuple(c[k] for c in cell_columns), tuple(data.GetPoint(i) for i in at),
                      tuple(tuple(c[i] for c in point_columns) for i in at)))
        k += 1
    return sorted(lines)


def check_streamlines(what, got, expected):
    """`got` holds the CLI's polylines, each once, with every array bit for bit."""
    got_lines, cli_lines = streamline_lines(got), streamline_lines(expected)
    if sorted(array_names(got.GetPointData())) != sorted(array_names(expected.GetPointData())) \
            or sorted(array_names(got.GetCellData())) != sorted(array_names(expected.GetCellData())):
        fail("%s: arrays %s / %s, the CLI's %s / %s" % (
            what, array_names(got.GetPointData()), array_names(got.GetCellData()),
            array_names(expected.GetPointData()), array_names(expected.GetCellData())))
    if got_lines != cli_lines:
        first = next((k for k in range(min(len(got_lines), len(cli_lines)))
                      if got_lines[k] != cli_lines[k]), min(len(got_lines), len(cli_lines)))
        fail("%s: %d lines, the CLI %d; first difference at sorted line %d" % (
            what, len(got_lines), len(cli_lines), first))
    return len(cli_lines), expected.GetNumberOfPoints()


def serial(args):
    texture, points, separatrices = cli_outputs(args)
    cli_streams = cli_streamlines(args)
    lic, topology, streamlines = plugin_proxies(args.input)
    lic.UpdatePipeline()
    got = sm.Fetch(lic)
    if got.GetExtent() != texture.GetExtent():
        fail("LIC extent %s, CLI %s" % (got.GetExtent(), texture.GetExtent()))
    check_same_texture("LIC", got, texture, got.GetExtent())
    masked = int(values(texture.GetPointData().GetArray("lic_mask")).sum())
    colours = len(np.unique(values(texture.GetPointData().GetArray("lic_color")), axis=0))
    if colours < 100:
        fail("the CLI picture's texture has %d colours: no blend with %s to compare"
             % (colours, BLEND_SCALAR))
    if masked == 0:
        fail("the CLI masks no pixel of %s: the input checks no mask (use a snapshot with solids)"
             % args.input)
    topology.UpdatePipeline()
    check_same_points("critical points", sm.Fetch(topology, None, None, 0), points)
    got_lines = separatrix_lines(sm.Fetch(topology, None, None, 1))
    if got_lines != separatrix_lines(separatrices):
        fail("separatrices differ from the CLI's")
    print("serial: LIC %s px bit-equal (%d masked), lic_color blended with %s equal to the CLI "
          "picture's pixels (%d colours)" % (texture.GetDimensions()[:2], masked, BLEND_SCALAR,
                                             colours))
    print("serial: %d critical points and %d separatrices "
          "bit-equal" % (points.GetNumberOfPoints(), len(got_lines)))
    for name, proxy in streamlines.items():
        proxy.UpdatePipeline()
        cells = cli_streams[name].GetCellData()
        ends = np.concatenate([values(cells.GetArray("reason")),
                               values(cells.GetArray("reason_backward"))])
        legend = list(values(cli_streams[name].GetFieldData().GetAbstractArray("reason_names")))
        # The rollers' mask seen: lines ending at them, or seeds on them (no line, seed_id skips).
        at_mask = int((ends == legend.index("nan_in_field")).sum())
        seeds_on_mask = int(values(cells.GetArray("seed_id")).max()) + 1 - len(ends) // 2
        if at_mask + seeds_on_mask == 0:
            fail("streamlines (%s): no CLI line ends at a masked node or starts on one" % name)
        count, npoints = check_streamlines("streamlines (%s)" % name, sm.Fetch(proxy),
                                           cli_streams[name])
        print("serial: streamlines (%s): %d lines, %d points bit-equal to fluidviz streamlines "
              "(%d line ends at masked nodes, %d seeds on them)"
              % (name, count, npoints, at_mask, seeds_on_mask))
    particles, grid = cli_resampled(args)
    resample = resample_proxy(particles)
    resample.UpdatePipeline()
    got = sm.Fetch(resample)
    if got.GetExtent() != grid.GetExtent():
        fail("resample: extent %s, CLI %s" % (got.GetExtent(), grid.GetExtent()))
    check_same_grid("resample", got, grid, got.GetExtent())
    if unsupported_nodes(grid) == 0:
        fail("resample: the CLI grid has no unsupported node; the test needs some")
    print("serial: resample: %s nodes, %d arrays bit-equal to fluidviz resample (%d unsupported)"
          % (grid.GetDimensions(), len(array_names(grid.GetPointData())),
             unsupported_nodes(grid)))


def parallel(args):
    ranks = sm.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
    if ranks != 2:
        fail("run under mpirun -np 2 (ranks: %d)" % ranks)
    texture, points, separatrices = cli_outputs(args)
    cli_streams = cli_streamlines(args)
    lic, topology, streamlines = plugin_proxies(args.input)
    lic.UpdatePipeline()
    rows = set()
    for rank in range(ranks):
        piece = sm.Fetch(lic, rank)
        extent = piece.GetExtent()
        if piece.GetNumberOfPoints() == 0:
            fail("LIC: rank %d holds no piece" % rank)
        check_same_texture("LIC rank %d" % rank, piece, texture, extent, geometry_tolerance=1e-5)
        rows.update(range(extent[2], extent[3] + 1))
        print("LIC rank %d: extent %s equal to the CLI's pixels" % (rank, extent))
    whole = texture.GetExtent()
    if rows != set(range(whole[2], whole[3] + 1)):
        fail("LIC: the ranks' pieces do not cover every row of %s" % (whole,))
    topology.UpdatePipeline()
    got = sm.Fetch(topology, None, None, 0)  # every rank's points, appended
    per_rank = [sm.Fetch(topology, rank).GetNumberOfPoints() for rank in range(ranks)]
    if min(per_rank) == 0:
        fail("critical points: a rank found none (%s); the test needs both to hold some" % per_rank)
    order = np.lexsort(vtk_to_numpy(got.GetPoints().GetData()).T[::-1])
    reference = np.lexsort(vtk_to_numpy(points.GetPoints().GetData()).T[::-1])
    if got.GetNumberOfPoints() != points.GetNumberOfPoints():
        fail("critical points: %d over the ranks (%s), the CLI %d" % (
            got.GetNumberOfPoints(), per_rank, points.GetNumberOfPoints()))
    if not np.array_equal(vtk_to_numpy(got.GetPoints().GetData())[order],
                          vtk_to_numpy(points.GetPoints().GetData())[reference]):
        fail("critical points: positions over the ranks differ from the CLI's")
    for name in array_names(points.GetPointData()):
        g = values(got.GetPointData().GetAbstractArray(name))[order]
        e = values(points.GetPointData().GetAbstractArray(name))[reference]
        if not np.array_equal(g, e):
            fail("critical points: array %s over the ranks differs from the CLI's" % name)
    got_lines = separatrix_lines(sm.Fetch(topology, None, None, 1))
    cli_lines = separatrix_lines(separatrices)
    if got_lines != cli_lines:
        first = next(k for k in range(min(len(got_lines), len(cli_lines)))
                     if got_lines[k] != cli_lines[k])
        fail("separatrices over the ranks differ from the CLI's (%d lines, CLI %d); line %d: "
             "%s ... vs %s ..." % (len(got_lines), len(cli_lines), first,
                                   str(got_lines[first])[:300], str(cli_lines[first])[:300]))
    print("parallel: %d critical points (%s per rank), each once, and %d whole separatrices "
          "equal to the CLI's" % (got.GetNumberOfPoints(), per_rank, len(got_lines)))
    for name, proxy in streamlines.items():
        proxy.UpdatePipeline()
        per_rank = [sm.Fetch(proxy, rank).GetNumberOfLines() for rank in range(ranks)]
        if min(per_rank) == 0:
            fail("streamlines (%s): a rank kept none (%s); the test needs both to hold some"
                 % (name, per_rank))
        # Every rank's lines, appended: the CLI's lines, each once (a line kept by both ranks
        # would be there twice, one kept by none missing), whole and with their serial seed_id.
        count, _ = check_streamlines("streamlines (%s) over the ranks" % name, sm.Fetch(proxy),
                                     cli_streams[name])
        print("parallel: streamlines (%s): %d lines (%s per rank), each once, equal to the "
              "CLI's" % (name, count, per_rank))
    particles, grid = cli_resampled(args)
    resample = resample_proxy(particles)
    resample.UpdatePipeline()
    nodes = 0
    for rank in range(ranks):
        piece = sm.Fetch(resample, rank)
        if piece.GetNumberOfPoints() == 0:
            fail("resample: rank %d holds no piece" % rank)
        check_same_grid("resample rank %d" % rank, piece, grid, piece.GetExtent(),
                        geometry_tolerance=1e-5)
        nodes += piece.GetNumberOfPoints()
        print("resample rank %d: extent %s equal to the CLI's nodes" % (rank, piece.GetExtent()))
    # Two pieces share one layer of nodes: together they are the grid, each node once but those.
    e, d = grid.GetExtent(), grid.GetDimensions()
    shared = min(nodes - grid.GetNumberOfPoints(), grid.GetNumberOfPoints())
    if shared not in (d[0], d[1]):
        fail("resample: the pieces hold %d nodes, the grid %d: not two blocks sharing a layer"
             % (nodes, grid.GetNumberOfPoints()))
    print("parallel: resample: the ranks' pieces are the CLI grid %s" % (d,))


def bad_property(args):
    reader = XMLImageDataReader(FileName=args.input)
    reader.UpdatePipeline()
    lic = FluidvizLIC(Input=reader, InputVectors=["POINTS", "velocity"], Length=5000)
    lic.UpdatePipeline()
    if sm.Fetch(lic).GetPointData().GetArray("lic") is not None:
        fail("a LIC with Length 5000 produced a texture")
    print("bad-property: no texture for Length 5000")
    # A pair of properties that contradict each other (as the CLI's flags would): no lines.
    lines = FluidvizStreamlines(Input=reader, InputVectors=["POINTS", "velocity"],
                                IntegrationIntegrator="rk45", IntegrationMinStep=0.5,
                                IntegrationMaxStep=0.25)
    lines.UpdatePipeline()
    if sm.Fetch(lines).GetNumberOfLines() != 0:
        fail("streamlines with IntegrationMinStep > IntegrationMaxStep produced lines")
    print("bad-property: no streamlines for IntegrationMinStep 0.5 > IntegrationMaxStep 0.25")


def example_texture(args):
    """The texture examples/paraview/lic_in_pvpython.py wrote (--work: its file) is the one
    `fluidviz lic --vti` writes with the CLI's defaults at the same width."""
    expected = os.path.join(os.path.dirname(args.work), "cli_default_lic.vti")
    got = read_image(args.work)
    width = got.GetDimensions()[0]
    run([args.fluidviz, "lic", args.input, "-a", "velocity", "-o", expected + ".png", "--vti",
         expected, "--resolution", "%dx%d" % (width, got.GetDimensions()[1])])
    check_same_texture("example", got, read_image(expected), got.GetExtent())
    print("example: %s equals fluidviz lic --vti at %d px" % (args.work, width))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("mode", choices=["serial", "parallel", "bad-property", "example"])
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--fluidviz")
    parser.add_argument("--input", required=True)
    parser.add_argument("--work")
    args = parser.parse_args()
    if args.mode == "example":
        example_texture(args)
        return
    if args.work:
        os.makedirs(args.work, exist_ok=True)
    LoadPlugin(args.plugin, remote=False, ns=globals())
    {"serial": serial, "parallel": parallel, "bad-property": bad_property}[args.mode](args)


main()
