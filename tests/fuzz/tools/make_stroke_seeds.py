#!/usr/bin/python3
"""Stroke .vtp files (issue 20; filters/sketch/vtk/StrokeFiles.h): polylines with the speed as
cell data, as point data, or none (1 m/s), in the encodings VTK writes. Writes the seeds of the
fuzz target stroke_vtp into OUT, and with --example the spiral of examples/sketch/spiral.csv as a
.vtp (cell-data speed) to the path given.

Run with Debian's python3 and python3-vtk9:
  /usr/bin/python3 tests/fuzz/tools/make_stroke_seeds.py tests/fuzz/corpus/stroke_vtp
  /usr/bin/python3 tests/fuzz/tools/make_stroke_seeds.py --example examples/sketch/spiral.csv \
      examples/sketch/spiral.vtp
"""
import csv
import os
import sys

import vtk


def polydata(strokes, speed_on):
    """strokes: [(points [(x, y)], speed)]; speed_on: 'cell', 'point' or None."""
    points = vtk.vtkPoints()
    points.SetDataTypeToDouble()
    lines = vtk.vtkCellArray()
    cell_speed = vtk.vtkDoubleArray()
    cell_speed.SetName("speed")
    point_speed = vtk.vtkDoubleArray()
    point_speed.SetName("speed")
    for pts, speed in strokes:
        line = vtk.vtkPolyLine()
        line.GetPointIds().SetNumberOfIds(len(pts))
        for k, (x, y) in enumerate(pts):
            line.GetPointIds().SetId(k, points.InsertNextPoint(x, y, 0.0))
            point_speed.InsertNextValue(speed)
        lines.InsertNextCell(line)
        cell_speed.InsertNextValue(speed)
    poly = vtk.vtkPolyData()
    poly.SetPoints(points)
    poly.SetLines(lines)
    if speed_on == "cell":
        poly.GetCellData().AddArray(cell_speed)
    elif speed_on == "point":
        poly.GetPointData().AddArray(point_speed)
    return poly


def write(poly, path, mode, compressor=None):
    w = vtk.vtkXMLPolyDataWriter()
    w.SetFileName(path)
    w.SetInputData(poly)
    {"ascii": w.SetDataModeToAscii, "binary": w.SetDataModeToBinary,
     "appended": w.SetDataModeToAppended}[mode]()
    if mode == "appended":
        w.EncodeAppendedDataOff()
    if compressor is None:
        w.SetCompressorTypeToNone()
    else:
        w.SetCompressorTypeToZLib()
    w.Write()


def csv_strokes(path):
    strokes = []
    with open(path) as f:
        rows = csv.DictReader(line for line in f if not line.startswith("#"))
        last = None
        for r in rows:
            if r["stroke"] != last:
                strokes.append(([], float(r["speed"])))
                last = r["stroke"]
            strokes[-1][0].append((float(r["x"]), float(r["y"])))
    return strokes


def main():
    if sys.argv[1] == "--example":
        write(polydata(csv_strokes(sys.argv[2]), "cell"), sys.argv[3], "ascii")
        return
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    two = [([(0.0, 0.3), (0.5, 0.3), (0.995, 0.3)], 0.02), ([(0.0, 0.7), (0.995, 0.7)], 0.06)]
    write(polydata(two, "cell"), os.path.join(out, "cell_speed_ascii.vtp"), "ascii")
    write(polydata(two, "point"), os.path.join(out, "point_speed_binary_zlib.vtp"), "binary", "zlib")
    write(polydata(two, None), os.path.join(out, "no_speed_appended.vtp"), "appended")


if __name__ == "__main__":
    main()
