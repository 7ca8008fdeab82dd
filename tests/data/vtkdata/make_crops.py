# Crops of public VTK datasets for tests/data/vtkdata/ (see README.md there): run with Debian's
# /usr/bin/python3 (python3-vtk9) as  make_crops.py SOURCE_DIR OUT_DIR, SOURCE_DIR holding
# carotid.vtk and kitchen.vtk from VTK's data (VTKData/Data).
import sys
from vtkmodules.vtkIOLegacy import vtkDataSetReader, vtkDataSetWriter
from vtkmodules.vtkImagingCore import vtkExtractVOI
from vtkmodules.vtkFiltersGeneral import vtkPassArrays
from vtkmodules.vtkCommonDataModel import vtkDataObject

src, out = sys.argv[1], sys.argv[2]

def read(name):
    r = vtkDataSetReader(); r.SetFileName(f"{src}/{name}"); r.ReadAllScalarsOn(); r.ReadAllVectorsOn(); r.Update()
    return r.GetOutput()

def write(data, name):
    w = vtkDataSetWriter(); w.SetInputData(data); w.SetFileName(f"{out}/{name}"); w.SetFileTypeToBinary()
    assert w.Write() == 1

# Carotid (PC-MRI velocity, 76 x 49 x 45 structured points): the 40 x 36 x 24 block around the
# bifurcation, velocity and the magnitude image ("scalars").
voi = vtkExtractVOI(); voi.SetInputData(read("carotid.vtk")); voi.SetVOI(20, 59, 4, 39, 10, 33); voi.Update()
write(voi.GetOutput(), "carotid_bifurcation.vtk")

# Kitchen (ventilated room CFD, 28 x 24 x 17 structured grid): whole, its velocity only.
keep = vtkPassArrays(); keep.SetInputData(read("kitchen.vtk"))
keep.AddArray(vtkDataObject.POINT, "velocity"); keep.Update()
write(keep.GetOutput(), "kitchen_velocity.vtk")
