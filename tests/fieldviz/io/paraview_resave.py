"""Re-save a .vti through ParaView, the way a user would hand one to fluidviz.

    pvbatch paraview_resave.py IN.vti OUT.vti

Adds twice_density = 2 * density as a Float32 array (ParaView's Calculator), so OUT holds both
double arrays passed through unchanged and a float array; compare_paraview_vti checks both.
"""
import sys

from paraview import simple

source = simple.OpenDataFile(sys.argv[1])
calculator = simple.Calculator(Input=source, ResultArrayName="twice_density",
                               Function="2*density", ResultArrayType="Float")
simple.SaveData(sys.argv[2], proxy=calculator)
