"""LIC of a fluidviz snapshot inside ParaView, with the fluidviz plugin (paraview/, issue 17).

Run README command 1 first (it writes out/four_roll_mill/, the default scene's snapshots), build
the plugin (bash scripts/build_paraview_plugin.sh prints its path), then:

  PYTHONPATH=build/paraview-python/usr/lib/python3/dist-packages \
    pvbatch examples/paraview/lic_in_pvpython.py \
      --plugin build/paraview-plugin/lib/fluidviz/Fluidviz/Fluidviz.so

It loads the plugin, reads the last snapshot, runs the FluidvizLIC proxy with the default scene's
settings (examples/four_roll_mill.json, output.lic: 800 px wide, fast method, L = 20 px; the other
properties keep the declared defaults, as in the scene) and saves the texture (`lic` in [0, 1],
`lic_mask`) as image data, the texture of the scene's picture out/four_roll_mill_lic_speed.png.
Open it in ParaView and colour by `lic` (Grayscale), or Calculator-blend it with the speed.

The rollers are masked as `fluidviz lic` masks them (the snapshot's vtkValidPointMask, NaN nodes
and no-slip solids): `lic_mask` is 1 there; threshold it away or colour it grey.
"""
import argparse
import glob
import os

from paraview.simple import LoadPlugin, SaveData, XMLImageDataReader

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--plugin", required=True, help="Fluidviz.so (scripts/build_paraview_plugin.sh)")
parser.add_argument("--input", default=None,
                    help="a snapshot .vti; default: the last of out/four_roll_mill/")
parser.add_argument("--output", default="out/four_roll_mill_lic_paraview.vti")
parser.add_argument("--width", type=int, default=800, help="texture width, px (the scene's)")
args = parser.parse_args()

snapshot = args.input or sorted(glob.glob("out/four_roll_mill/four_roll_mill_*.vti"))[-1]
LoadPlugin(args.plugin, remote=False, ns=globals())
reader = XMLImageDataReader(FileName=snapshot)
reader.UpdatePipeline()  # fills the array list, so that InputVectors can be chosen
lic = FluidvizLIC(Input=reader, InputVectors=["POINTS", "velocity"],
                  Width=args.width, Method="fast", Length=20.0)
os.makedirs(os.path.dirname(os.path.abspath(args.output)), exist_ok=True)
SaveData(args.output, proxy=lic)
print("wrote %s (LIC of 'velocity' in %s)" % (args.output, snapshot))
