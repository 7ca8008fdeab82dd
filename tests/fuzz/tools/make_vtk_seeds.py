# Seeds for tests/fuzz/corpus: tiny .vti/.vtp files in every encoding VTK's XML readers accept.
import sys, os
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPolyData, vtkCellArray
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkFloatArray, vtkIntArray, vtkPoints, vtkUnsignedCharArray
from vtkmodules.vtkIOXML import vtkXMLImageDataWriter, vtkXMLPolyDataWriter
out = sys.argv[1]
os.makedirs(out + "/vti_reader", exist_ok=True); os.makedirs(out + "/vtp_reader", exist_ok=True)

def image(nz=1, float32=False):
    im = vtkImageData(); im.SetDimensions(3, 2, nz); im.SetSpacing(0.5, 0.5, 1.0); im.SetOrigin(0, 0, 0)
    n = im.GetNumberOfPoints()
    v = (vtkFloatArray if float32 else vtkDoubleArray)(); v.SetName("velocity"); v.SetNumberOfComponents(3)
    d = vtkDoubleArray(); d.SetName("density"); d.SetNumberOfComponents(1)
    f = vtkIntArray(); f.SetName("flag"); f.SetNumberOfComponents(1)
    for i in range(n):
        v.InsertNextTuple3(0.1 * i, -0.2 * i, 0.0); d.InsertNextValue(1.0 + 0.01 * i); f.InsertNextValue(i % 2)
    pd = im.GetPointData(); pd.AddArray(v); pd.AddArray(d); pd.AddArray(f); pd.SetActiveVectors("velocity")
    return im

def particles(nz=False):
    p = vtkPoints(); verts = vtkCellArray()
    for i in range(4):
        p.InsertNextPoint(0.1 * i, 0.05 * i, 0.02 * i if nz else 0.0); verts.InsertNextCell(1); verts.InsertCellPoint(i)
    poly = vtkPolyData(); poly.SetPoints(p); poly.SetVerts(verts)
    v = vtkFloatArray(); v.SetName("velocity"); v.SetNumberOfComponents(2)
    rho = vtkDoubleArray(); rho.SetName("density")
    for i in range(4): v.InsertNextTuple2(i, -i); rho.InsertNextValue(1000 + i)
    poly.GetPointData().AddArray(v); poly.GetPointData().AddArray(rho)
    return poly

def configure(w, mode, compressor, header64):
    {"ascii": w.SetDataModeToAscii, "binary": w.SetDataModeToBinary,
     "appended": w.SetDataModeToAppended, "raw": w.SetDataModeToAppended}[mode]()
    if mode == "raw": w.EncodeAppendedDataOff()
    if compressor == "none": w.SetCompressorTypeToNone()
    elif compressor == "zlib": w.SetCompressorTypeToZLib()
    elif compressor == "lz4": w.SetCompressorTypeToLZ4()
    elif compressor == "lzma": w.SetCompressorTypeToLZMA()
    if header64: w.SetHeaderTypeToUInt64()

cases = [("ascii", "none", False), ("binary", "none", False), ("binary", "zlib", True),
         ("appended", "none", False), ("raw", "none", True), ("raw", "zlib", True),
         ("raw", "lz4", False), ("raw", "lzma", False)]
for mode, comp, h64 in cases:
    for nz, f32, tag in [(1, False, "2d"), (2, True, "3d_float")]:
        w = vtkXMLImageDataWriter(); configure(w, mode, comp, h64); w.SetInputData(image(nz, f32))
        w.SetFileName(f"{out}/vti_reader/{tag}_{mode}_{comp}.vti"); assert w.Write() == 1
    for nz, tag in [(False, "2d"), (True, "3d")]:
        w = vtkXMLPolyDataWriter(); configure(w, mode, comp, h64); w.SetInputData(particles(nz))
        w.SetFileName(f"{out}/vtp_reader/{tag}_{mode}_{comp}.vtp"); assert w.Write() == 1
