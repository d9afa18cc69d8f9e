"""Opens a run's fields.xdmf with ParaView's own XDMF reader and prints what it finds: the check that
ParaView reads Chute's output as it is (not run in CI: ParaView is a large install).

    apt-get install -y --no-install-recommends paraview python3-paraview
    pvbatch tools/check_xdmf_in_paraview.py results/cavity_re100/fields.xdmf
"""
from paraview.simple import *
import sys
r = XDMFReader(FileNames=[sys.argv[1]])
r.UpdatePipelineInformation()
times = r.TimestepValues
print("timesteps:", len(times), times[:3], "...", times[-1])
r.UpdatePipeline(times[-1])
info = r.GetDataInformation()
print("cells:", info.GetNumberOfCells(), "points:", info.GetNumberOfPoints())
cd = r.CellData
for name in cd.keys():
    print(name, cd[name].GetRange())
