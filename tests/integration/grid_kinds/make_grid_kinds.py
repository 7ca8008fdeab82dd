"""Writes one analytic thin-3D flow as every file kind fluidviz reads (tests/integration/grid_kinds).

Field on [0, 1] x [0, 1] x [0, 0.1875], nodes 1/16 apart (17 x 17 x 4; every coordinate exact in
float32, so that probing the .vtp's quads finds the nodes on them):
  v = (-(y - YC), x - XC, 0)     a rigid rotation: one centre at (XC, YC), off the nodes
  s = (x - XC)^2 + (y - YC)^2    its level set s = R^2 is a cylinder of radius R around the centre
Both are linear/quadratic in x, y, so each kind resampled at the nodes' spacing gives back the
same grid values (the cell-data .vti: averages of the cell-centre values, exact for v inside).

Usage: make_grid_kinds.py OUT_DIR
"""
import os
import sys

import vtk
from vtk.util import numpy_support as ns
import numpy as np

XC, YC = 0.53, 0.47
H = 0.0625
N = (17, 17, 4)


def image():
    img = vtk.vtkImageData()
    img.SetDimensions(*N)
    img.SetSpacing(H, H, H)
    return img


def add_arrays(data, xyz, attributes):
    x, y = xyz[:, 0], xyz[:, 1]
    v = np.stack([-(y - YC), x - XC, np.zeros_like(x)], axis=1)
    s = (x - XC) ** 2 + (y - YC) ** 2
    va = ns.numpy_to_vtk(v, deep=1)
    va.SetName("v")
    sa = ns.numpy_to_vtk(s, deep=1)
    sa.SetName("s")
    attributes.AddArray(va)
    attributes.AddArray(sa)


def point_image():
    img = image()
    xyz = np.array([img.GetPoint(i) for i in range(img.GetNumberOfPoints())])
    add_arrays(img, xyz, img.GetPointData())
    return img


def cell_image():
    img = image()
    centres = vtk.vtkCellCenters()
    centres.SetInputData(img)
    centres.Update()
    xyz = ns.vtk_to_numpy(centres.GetOutput().GetPoints().GetData())
    add_arrays(img, xyz, img.GetCellData())
    return img


def rectilinear():
    grid = vtk.vtkRectilinearGrid()
    grid.SetDimensions(*N)
    for axis, setter in enumerate((grid.SetXCoordinates, grid.SetYCoordinates,
                                   grid.SetZCoordinates)):
        setter(ns.numpy_to_vtk(np.arange(N[axis]) * H, deep=1))
    xyz = np.array([grid.GetPoint(i) for i in range(grid.GetNumberOfPoints())])
    add_arrays(grid, xyz, grid.GetPointData())
    return grid


def points_of(img):
    pts = vtk.vtkPoints()
    for i in range(img.GetNumberOfPoints()):
        pts.InsertNextPoint(img.GetPoint(i))
    return pts


def structured():
    img = point_image()
    grid = vtk.vtkStructuredGrid()
    grid.SetDimensions(*N)
    grid.SetPoints(points_of(img))
    grid.GetPointData().ShallowCopy(img.GetPointData())
    return grid


def unstructured(img=None):
    append = vtk.vtkAppendFilter()
    append.AddInputData(img if img is not None else point_image())
    append.Update()
    return append.GetOutput()


def poly_layers():
    """Quads of every z layer: the probe finds a node only on them (within VTK's tolerance)."""
    append = vtk.vtkAppendPolyData()
    for k in range(N[2]):
        layer = vtk.vtkImageDataGeometryFilter()
        layer.SetInputData(point_image())
        layer.SetExtent(0, N[0] - 1, 0, N[1] - 1, k, k)
        append.AddInputConnection(layer.GetOutputPort())
    append.Update()
    return append.GetOutput()


def write(writer, data, path):
    writer.SetInputData(data)
    writer.SetFileName(path)
    if not writer.Write():
        sys.exit("cannot write " + path)


def half(img, x0, x1):
    clip = vtk.vtkExtractVOI()
    clip.SetInputData(img)
    clip.SetVOI(x0, x1, 0, N[1] - 1, 0, N[2] - 1)
    clip.Update()
    return clip.GetOutput()


def multiblock(out):
    """Two blocks of different kinds: an image (x <= 0.5) and an unstructured grid (x >= 0.5)."""
    img = point_image()
    blocks = vtk.vtkMultiBlockDataSet()
    blocks.SetBlock(0, half(img, 0, 8))
    blocks.SetBlock(1, unstructured(half(img, 8, N[0] - 1)))
    write(vtk.vtkXMLMultiBlockDataWriter(), blocks, os.path.join(out, "blocks.vtm"))


def parallel(writer, data, path):
    writer.SetNumberOfPieces(2)
    writer.SetStartPiece(0)
    writer.SetEndPiece(1)
    write(writer, data, path)


def main():
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    write(vtk.vtkXMLImageDataWriter(), point_image(), os.path.join(out, "points.vti"))
    write(vtk.vtkXMLImageDataWriter(), cell_image(), os.path.join(out, "cells.vti"))
    write(vtk.vtkXMLRectilinearGridWriter(), rectilinear(), os.path.join(out, "grid.vtr"))
    write(vtk.vtkXMLStructuredGridWriter(), structured(), os.path.join(out, "grid.vts"))
    write(vtk.vtkXMLUnstructuredGridWriter(), unstructured(), os.path.join(out, "grid.vtu"))
    write(vtk.vtkXMLPolyDataWriter(), poly_layers(), os.path.join(out, "layers.vtp"))
    parallel(vtk.vtkXMLPImageDataWriter(), point_image(), os.path.join(out, "pieces.pvti"))
    parallel(vtk.vtkXMLPUnstructuredGridWriter(), unstructured(), os.path.join(out, "pieces.pvtu"))
    multiblock(out)
    legacy = vtk.vtkStructuredGridWriter()
    legacy.SetFileTypeToBinary()
    write(legacy, structured(), os.path.join(out, "legacy.vtk"))


if __name__ == "__main__":
    main()
