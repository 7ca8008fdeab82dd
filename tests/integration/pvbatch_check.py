"""Check that ParaView itself reads a fluidviz time series (.pvd), or single files, completely and sensibly.

Run with ParaView's batch interpreter, with python3-paraview on PYTHONPATH
(scripts/setup_paraview.sh DIR prints the PYTHONPATH to use on its last line):

    PYTHONPATH=DIR/usr/lib/python3/dist-packages pvbatch tests/integration/pvbatch_check.py \
        out/flow.pvd --arrays velocity,density,speed --points 4096 [--steps 3]

For every time step the series offers (reader.TimestepValues) it checks that the step loads, has
each expected point array with the expected number of components, the expected number of points,
and only finite values (VTK's ranges skip NaN, so the values themselves are scanned). Before that
it checks that every file the .pvd lists exists. One summary line is printed per step.

Given other files than one .pvd (any file ParaView opens: .vtp, .vti, ...), each is checked as
one step (it loads, has the arrays, only finite values; --points and --steps do not apply):

    pvbatch tests/integration/pvbatch_check.py a/iso.vtp b/iso.vtp --arrays s,v:3

--arrays takes NAME or NAME:COMPONENTS; without COMPONENTS, 'velocity' means 3 and any other name 1.

Exit codes (stable, so CMake tests can tell a failed check from a crash):
    0  every check passed
    2  bad command line (argparse)
    3  a check failed: each failure is printed on a line starting "pvbatch_check: FAIL"
    4  the .pvd itself is missing or not a VTK collection
 pvbatch exits 1 when the script raises, e.g. when paraview.simple cannot be imported.
"""

import argparse
import math
import os
import sys
import xml.etree.ElementTree as ElementTree

EXIT_OK = 0
EXIT_CHECK_FAILED = 3
EXIT_BAD_SERIES = 4


def parse_arguments(argv):
    parser = argparse.ArgumentParser(prog="pvbatch_check.py", description=__doc__.split("\n")[0])
    parser.add_argument("inputs", nargs="+", help="the .pvd series, or data files, to check")
    parser.add_argument("--arrays", default="", help="NAME[:COMPONENTS],... expected point arrays")
    parser.add_argument("--points", type=int, help="expected number of points in every step")
    parser.add_argument("--steps", type=int, help="expected number of time steps")
    return parser.parse_args(argv)


def expected_arrays(spec):
    """'velocity,density:1,q:9' -> [('velocity', 3), ('density', 1), ('q', 9)]"""
    arrays = []
    for item in filter(None, (s.strip() for s in spec.split(","))):
        name, _, components = item.partition(":")
        arrays.append((name, int(components) if components else (3 if name == "velocity" else 1)))
    return arrays


def fail_early(message):
    print("pvbatch_check: FAIL: " + message, flush=True)
    sys.exit(EXIT_BAD_SERIES)


def listed_files(pvd):
    """(timestep, file) of every DataSet of the collection, file relative to the .pvd's folder."""
    if not os.path.isfile(pvd):
        fail_early("series %s does not exist" % pvd)
    try:
        root = ElementTree.parse(pvd).getroot()
    except ElementTree.ParseError as error:
        fail_early("series %s is not valid XML: %s" % (pvd, error))
    if root.tag != "VTKFile" or root.get("type") != "Collection":
        fail_early("series %s is not a VTK collection (<VTKFile type=\"Collection\">)" % pvd)
    return [(d.get("timestep"), d.get("file") or "") for d in root.iter("DataSet")]


def missing_files(pvd, entries):
    folder = os.path.dirname(os.path.abspath(pvd))
    return ["file %s listed for timestep %s in %s does not exist" % (f, t, pvd)
            for t, f in entries if not os.path.isfile(os.path.join(folder, f))]


def leaf_datasets(data):
    """The datasets of a (possibly composite) output."""
    if not data.IsA("vtkCompositeDataSet"):
        return [data]
    leaves = []
    iterator = data.NewIterator()
    iterator.InitTraversal()
    while not iterator.IsDoneWithTraversal():
        leaves.append(iterator.GetCurrentDataObject())
        iterator.GoToNextItem()
    return leaves


def count_non_finite(array):
    try:
        import numpy
        from vtkmodules.util.numpy_support import vtk_to_numpy
        return int(numpy.count_nonzero(~numpy.isfinite(vtk_to_numpy(array))))
    except ImportError:  # numpy is optional: scan in pure Python
        n = array.GetNumberOfTuples() * array.GetNumberOfComponents()
        return sum(1 for i in range(n) if not math.isfinite(array.GetValue(i)))


def check_array(leaves, name, components):
    """(problems, summary) for one point array over all leaves of one step."""
    arrays = [leaf.GetPointData().GetArray(name) for leaf in leaves]
    if any(a is None for a in arrays):
        present = sorted({leaf.GetPointData().GetArrayName(i) for leaf in leaves
                          for i in range(leaf.GetPointData().GetNumberOfArrays())})
        return ["no point array '%s' (present: %s)" % (name, ", ".join(present) or "none")], None
    problems = []
    found = {a.GetNumberOfComponents() for a in arrays}
    if found != {components}:
        problems.append("array '%s' has %s components, expected %d"
                        % (name, "/".join(map(str, sorted(found))), components))
    bad = sum(count_non_finite(a) for a in arrays)
    if bad:
        problems.append("array '%s' has %d NaN or infinite values" % (name, bad))
    low = min(a.GetRange(-1)[0] for a in arrays)
    high = max(a.GetRange(-1)[1] for a in arrays)
    return problems, "%s(%d) [%.6g, %.6g]" % (name, arrays[0].GetNumberOfComponents(), low, high)


def check_step(reader, time, arrays, points):
    """(problems, summary line) of one time step."""
    from paraview import servermanager
    if time is None:
        reader.UpdatePipeline()
    else:
        reader.UpdatePipeline(time)
    data = servermanager.Fetch(reader)
    leaves = [leaf for leaf in leaf_datasets(data) if leaf is not None] if data else []
    if not leaves:
        return ["the step did not load (no data)"], "no data"
    problems, parts = [], []
    count = sum(leaf.GetNumberOfPoints() for leaf in leaves)
    parts.append("%d points" % count)
    if points is not None and count != points:
        problems.append("%d points, expected %d" % (count, points))
    for name, components in arrays:
        array_problems, summary = check_array(leaves, name, components)
        problems += array_problems
        if summary:
            parts.append(summary)
    return problems, "; ".join(parts)


def timestep_values(reader):
    values = reader.TimestepValues
    if values is None:
        return []
    return list(values) if hasattr(values, "__len__") else [values]


def check_files(files, arrays):
    """Each file as one step: the exit code."""
    from paraview import simple
    failures = []
    for path in files:
        if not os.path.isfile(path):
            failures.append("file %s does not exist" % path)
            continue
        reader = simple.OpenDataFile(os.path.abspath(path))
        if reader is None:
            failures.append("ParaView cannot open %s" % path)
            continue
        problems, summary = check_step(reader, None, arrays, None)
        print("%s: %s: %s" % (path, summary, "FAIL" if problems else "ok"), flush=True)
        failures += ["%s: %s" % (path, p) for p in problems]
        simple.Delete(reader)
    for failure in failures:
        print("pvbatch_check: FAIL: " + failure, flush=True)
    if failures:
        return EXIT_CHECK_FAILED
    print("pvbatch_check: OK: %d files" % len(files), flush=True)
    return EXIT_OK


def main(argv):
    options = parse_arguments(argv)
    arrays = expected_arrays(options.arrays)
    if len(options.inputs) > 1 or not options.inputs[0].endswith(".pvd"):
        return check_files(options.inputs, arrays)
    options.pvd = options.inputs[0]
    entries = listed_files(options.pvd)
    failures = missing_files(options.pvd, entries)

    from paraview import simple
    reader = simple.OpenDataFile(os.path.abspath(options.pvd))
    if reader is None:
        fail_early("ParaView cannot open %s" % options.pvd)
    times = timestep_values(reader)
    if not times:
        failures.append("the series has no time steps")
    if options.steps is not None and len(times) != options.steps:
        failures.append("%d time steps, expected %d" % (len(times), options.steps))

    for step, time in enumerate(times):
        problems, summary = check_step(reader, time, arrays, options.points)
        print("step %d t=%.9g: %s: %s" % (step, time, summary, "FAIL" if problems else "ok"), flush=True)
        failures += ["step %d (t=%.9g): %s" % (step, time, p) for p in problems]

    for failure in failures:
        print("pvbatch_check: FAIL: " + failure, flush=True)
    if failures:
        return EXIT_CHECK_FAILED
    print("pvbatch_check: OK: %d time steps of %s" % (len(times), options.pvd), flush=True)
    return EXIT_OK


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
