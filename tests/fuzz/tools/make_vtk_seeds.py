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

# Legacy .vtk seeds: every dataset type, ASCII and BINARY, as VTK's vtkDataSetWriter writes them
# (version 5.1: OFFSETS/CONNECTIVITY), each with a "velocity" vector, a scalar and field data.
from vtkmodules.vtkCommonDataModel import (vtkStructuredPoints, vtkStructuredGrid, vtkRectilinearGrid,
                                           vtkUnstructuredGrid, VTK_QUAD, VTK_TRIANGLE)
from vtkmodules.vtkIOLegacy import vtkDataSetWriter
os.makedirs(out + "/vtk_legacy_reader", exist_ok=True)

def with_arrays(ds):
    v = vtkFloatArray(); v.SetName("velocity"); v.SetNumberOfComponents(3)
    s = vtkDoubleArray(); s.SetName("pressure")
    for i in range(ds.GetNumberOfPoints()):
        x = ds.GetPoint(i); v.InsertNextTuple3(1 + x[0] - x[1], 0.5 * x[0], 0.0); s.InsertNextValue(x[0] + x[1])
    ds.GetPointData().AddArray(v); ds.GetPointData().SetVectors(v); ds.GetPointData().SetScalars(s)
    f = vtkIntArray(); f.SetName("step"); f.InsertNextValue(3); ds.GetFieldData().AddArray(f)
    return ds

def legacy_datasets():
    sp = vtkStructuredPoints(); sp.SetDimensions(3, 2, 2); sp.SetSpacing(0.5, 0.5, 1.0)
    pts = vtkPoints()
    for j in range(2):
        for i in range(3): pts.InsertNextPoint(0.5 * i + 0.1 * j, 0.5 * j, 0)
    sg = vtkStructuredGrid(); sg.SetDimensions(3, 2, 1); sg.SetPoints(pts)
    rg = vtkRectilinearGrid(); rg.SetDimensions(3, 2, 1)
    for setter, values in ((rg.SetXCoordinates, (0, 0.3, 1)), (rg.SetYCoordinates, (0, 1)), (rg.SetZCoordinates, (0,))):
        c = vtkDoubleArray()
        for x in values: c.InsertNextValue(x)
        setter(c)
    ug = vtkUnstructuredGrid(); ug.SetPoints(pts)
    ug.InsertNextCell(VTK_QUAD, 4, [0, 1, 4, 3]); ug.InsertNextCell(VTK_TRIANGLE, 3, [1, 2, 5])
    pd = vtkPolyData(); pd.SetPoints(pts); tris = vtkCellArray()
    for t in ([0, 1, 4], [0, 4, 3], [1, 2, 5], [1, 5, 4]):
        tris.InsertNextCell(3)
        for k in t: tris.InsertCellPoint(k)
    pd.SetPolys(tris)
    return [("structured_points", sp), ("structured_grid", sg), ("rectilinear_grid", rg),
            ("unstructured_grid", ug), ("polydata", pd)]

for name, ds in legacy_datasets():
    with_arrays(ds)
    for binary in (False, True):
        w = vtkDataSetWriter(); w.SetInputData(ds)
        w.SetFileName(f"{out}/vtk_legacy_reader/{name}_{'binary' if binary else 'ascii'}.vtk")
        (w.SetFileTypeToBinary if binary else w.SetFileTypeToASCII)()
        assert w.Write() == 1

# fuzz_vtk_xml_grids seeds: tiny .vtr/.vts/.vtu in a few encodings, and .pvti/.pvtu/.vtm summaries
# naming the fixed pieces piece.vti and piece.vtu that the target writes beside its input (a
# 3 x 2 x 1 image 0.5 apart with "velocity" and "density", fuzz_vtk_xml_grids.cpp pieceImage()).
from vtkmodules.vtkIOXML import (vtkXMLRectilinearGridWriter, vtkXMLStructuredGridWriter,
                                 vtkXMLUnstructuredGridWriter)
os.makedirs(out + "/vtk_xml_grids", exist_ok=True)
grids = {name: with_arrays(ds) for name, ds in legacy_datasets()}
grid_writers = [("vtr", vtkXMLRectilinearGridWriter, "rectilinear_grid"),
                ("vts", vtkXMLStructuredGridWriter, "structured_grid"),
                ("vtu", vtkXMLUnstructuredGridWriter, "unstructured_grid")]
for ext, writer, name in grid_writers:
    for mode, comp, h64 in [("ascii", "none", False), ("binary", "zlib", False), ("raw", "none", True),
                            ("raw", "lz4", False)]:
        w = writer(); configure(w, mode, comp, h64); w.SetInputData(grids[name])
        w.SetFileName(f"{out}/vtk_xml_grids/{name}_{mode}_{comp}.{ext}"); assert w.Write() == 1

arrays = ('<PDataArray type="Float64" Name="velocity" NumberOfComponents="3"/>'
          '<PDataArray type="Float64" Name="density"/>')
summaries = {
    "pieces.pvti": '<VTKFile type="PImageData" version="1.0" byte_order="LittleEndian">\n'
                   '<PImageData WholeExtent="0 2 0 1 0 0" GhostLevel="0" Origin="0 0 0" Spacing="0.5 0.5 1">\n'
                   f'<PPointData>{arrays}</PPointData>\n'
                   '<Piece Extent="0 2 0 1 0 0" Source="piece.vti"/>\n</PImageData>\n</VTKFile>\n',
    "pieces.pvtu": '<VTKFile type="PUnstructuredGrid" version="1.0" byte_order="LittleEndian">\n'
                   f'<PUnstructuredGrid GhostLevel="0">\n<PPointData>{arrays}</PPointData>\n'
                   '<PPoints><PDataArray type="Float32" NumberOfComponents="3"/></PPoints>\n'
                   '<Piece Source="piece.vtu"/>\n</PUnstructuredGrid>\n</VTKFile>\n',
    "blocks.vtm": '<VTKFile type="vtkMultiBlockDataSet" version="1.0" byte_order="LittleEndian">\n'
                  '<vtkMultiBlockDataSet>\n<DataSet index="0" file="piece.vti"/>\n'
                  '<Block index="1"><DataSet index="0" file="piece.vtu"/></Block>\n'
                  '</vtkMultiBlockDataSet>\n</VTKFile>\n',
}
for name, text in summaries.items():
    with open(f"{out}/vtk_xml_grids/{name}", "w") as f:
        f.write('<?xml version="1.0"?>\n' + text)
