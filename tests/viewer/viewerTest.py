"""Open a finished wavyShearFoam case with ParaView's own OpenFOAM reader and
check what a user sees: the Lagrangian cloud with N points and its arrays,
the Eulerian fields; then render the particles as spheres coloured by the
particle stress S_xy to a PNG.

    pvpython viewerTest.py <case> <N> <png>     (on an X display: Xvfb)
"""
import os
import sys

from paraview import simple as pv
from paraview import servermanager as sm

case, N, png = sys.argv[1], int(sys.argv[2]), sys.argv[3]
foam = os.path.join(case, "case.foam")
open(foam, "a").close()

reader = pv.OpenFOAMReader(FileName=foam)
reader.SkipZeroTime = 0
reader.UpdatePipelineInformation()
regions = list(reader.GetProperty("MeshRegions").Available)
assert "lagrangian/suspension" in regions, "no cloud among %s" % regions
reader.MeshRegions = ["internalMesh", "lagrangian/suspension"]
reader.CellArrays = ["Uinf", "gradUinf", "shearRateInf", "particleStress", "alpha"]
reader.LagrangianArrays = ["d", "U", "omega", "S", "origId"]
times = list(reader.TimestepValues)
assert len(times) >= 2, "expected several written times, got %s" % times
last = times[-1]
reader.UpdatePipeline(last)

data = sm.Fetch(reader)
blocks = {}
it = data.NewIterator()
it.InitTraversal()
while not it.IsDoneWithTraversal():
    name = it.GetCurrentMetaData().Get(data.NAME())
    blocks[name] = it.GetCurrentDataObject()
    it.GoToNextItem()

cloud = blocks.get("suspension")
mesh = blocks.get("internalMesh")
assert cloud is not None, "cloud block missing: %s" % list(blocks)
assert mesh is not None, "internalMesh block missing: %s" % list(blocks)

npts = cloud.GetNumberOfPoints()
assert npts == N, "cloud has %d points, expected %d" % (npts, N)
pd = cloud.GetPointData()
for name, comps in (("d", 1), ("U", 3), ("omega", 3), ("S", 6)):
    arr = pd.GetArray(name)
    assert arr is not None, "cloud array %s missing" % name
    assert arr.GetNumberOfComponents() == comps, "%s has %d components" % (name, arr.GetNumberOfComponents())
    assert arr.GetNumberOfTuples() == N
dmin, dmax = pd.GetArray("d").GetRange()
assert dmin > 0, "non-positive diameter %g" % dmin

cd = mesh.GetCellData()
for name, comps in (("Uinf", 3), ("gradUinf", 9), ("particleStress", 6), ("alpha", 1)):
    arr = cd.GetArray(name)
    assert arr is not None, "cell field %s missing" % name
    assert arr.GetNumberOfComponents() == comps
    assert arr.GetNumberOfTuples() == mesh.GetNumberOfCells()
amin, amax = cd.GetArray("alpha").GetRange()
assert 0 <= amin and amax > 0, "alpha range %g %g" % (amin, amax)

# Picture: the box outline, particles as spheres of their diameter coloured
# by S_xy (VTK order XX YY ZZ XY YZ XZ: component 3)
view = pv.CreateRenderView()
view.ViewSize = [900, 700]
if hasattr(view, "UseColorPaletteForBackground"):
    view.UseColorPaletteForBackground = 0
view.Background = [1, 1, 1]
view.OrientationAxesVisibility = 0
meshOnly = pv.ExtractBlock(Input=reader)
meshOnly.Selectors = ["/Root/internalMesh"]
outline = pv.Show(meshOnly, view)
outline.SetRepresentationType("Outline")
outline.AmbientColor = outline.DiffuseColor = [0.2, 0.2, 0.2]
cloudOnly = pv.ExtractBlock(Input=reader)
cloudOnly.Selectors = ["/Root/lagrangian/suspension"]
spheres = pv.Show(cloudOnly, view)
spheres.SetRepresentationType("Point Gaussian")
spheres.ShaderPreset = "Sphere"
spheres.ScaleByArray = 1
spheres.SetScaleArray = ["POINTS", "d"]
spheres.UseScaleFunction = 0
spheres.GaussianRadius = 0.5
pv.ColorBy(spheres, ("POINTS", "S", "3"))
lut = pv.GetColorTransferFunction("S")
lut.VectorMode = "Component"
lut.VectorComponent = 3
lut.ApplyPreset("Cool to Warm", True)
spheres.RescaleTransferFunctionToDataRange(False, True)
bar = pv.GetScalarBar(lut, view)
bar.Title = "particle stresslet S_xy"
bar.ComponentTitle = ""
bar.TitleColor = bar.LabelColor = [0, 0, 0]
spheres.SetScalarBarVisibility(view, True)
view.CameraPosition = [-1.2, 0.8, 2.2]
view.CameraFocalPoint = [0, 0, 0]
view.CameraViewUp = [0, 1, 0]
view.ResetCamera()
pv.Render(view)
pv.SaveScreenshot(png, view, ImageResolution=[900, 700])
assert os.path.getsize(png) > 10000, "screenshot too small"
print("viewer test: %d particles, arrays d U omega S; fields Uinf gradUinf particleStress alpha; wrote %s" % (npts, png))
