# Opens a tissue .pvd series with ParaView's PVD reader and checks its time steps and arrays.
#   pvpython pvd_read.py SERIES.pvd
import sys

from paraview import servermanager
from paraview.simple import GetParaViewVersion, PVDReader

ARRAYS = ["velocity_mm_per_s", "stretch", "strain", "contact_force_N", "plane_normal",
          "plane_offset_mm", "plane_residual_mm", "tangent", "normal"]

reader = PVDReader(FileName=sys.argv[1])
reader.UpdatePipelineInformation()
times = list(reader.TimestepValues)
if len(times) != 100:
    sys.exit(f"FAIL: {len(times)} time steps, expected 100")
if any(b <= a for a, b in zip(times, times[1:])):
    sys.exit("FAIL: time steps do not increase")
for t in (times[0], times[-1]):
    reader.UpdatePipeline(t)
    data = servermanager.Fetch(reader)
    points = data.GetNumberOfPoints()
    for name in ARRAYS:
        array = data.GetPointData().GetArray(name)
        if array is None:
            sys.exit(f"FAIL: array {name} missing at t = {t}")
        if array.GetNumberOfTuples() != points:
            sys.exit(f"FAIL: array {name} has {array.GetNumberOfTuples()} tuples for {points} points")
print(f"ParaView {GetParaViewVersion()}: 100 time steps {times[0]:.4f}..{times[-1]:.4f} s, {len(ARRAYS)} arrays on {points} points")
