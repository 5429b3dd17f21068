// The scene of each inspection view: which data set, which array and range, which overlays.
#include "view_scenes.h"

#include <vtkArrowSource.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSphereSource.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

#include "tissue/core/vec_math.h"
#include "vtk_io.h"

namespace tissue::inspect {
namespace {

vtkSmartPointer<vtkPolyData> surfacePoly(std::span<const Float3> positions,
                                         std::span<const Triangle> triangles) {
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(pointsOf(positions));
  vtkNew<vtkCellArray> cells;
  for (const Triangle& t : triangles) {
    const vtkIdType ids[3] = {vtkIdType(t[0]), vtkIdType(t[1]), vtkIdType(t[2])};
    cells->InsertNextCell(3, ids);
  }
  poly->SetPolys(cells);
  return poly;
}

vtkSmartPointer<vtkPolyData> linesPoly(std::span<const Float3> positions, std::span<const Edge> edges) {
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(pointsOf(positions));
  vtkNew<vtkCellArray> cells;
  for (const Edge& e : edges) {
    const vtkIdType ids[2] = {vtkIdType(e[0]), vtkIdType(e[1])};
    cells->InsertNextCell(2, ids);
  }
  poly->SetLines(cells);
  return poly;
}

/// Every `stride`-th origin's direction as a line segment of `length` mm.
vtkSmartPointer<vtkPolyData> glyphLines(std::span<const Float3> origins, std::span<const Float3> directions,
                                        float length, std::size_t stride) {
  std::vector<Float3> points;
  std::vector<Edge> edges;
  for (std::size_t i = 0; i < origins.size(); i += stride) {
    const auto a = std::uint32_t(points.size());
    points.push_back(origins[i]);
    points.push_back(origins[i] + length * directions[i]);
    edges.push_back({a, a + 1});
  }
  return linesPoly(points, edges);
}

vtkSmartPointer<vtkPolyData> markers(std::span<const Float3> positions) {
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(pointsOf(positions));
  vtkNew<vtkCellArray> verts;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const vtkIdType id = vtkIdType(i);
    verts->InsertNextCell(1, &id);
  }
  poly->SetVerts(verts);
  return poly;
}

/// VTK's arrow (along +x, length 1) turned onto `direction` and scaled to `length` mm at `from`.
vtkSmartPointer<vtkPolyData> arrow(Float3 from, Float3 direction, float length) {
  vtkNew<vtkArrowSource> source;
  source->SetTipResolution(24);
  source->SetShaftResolution(24);
  source->SetShaftRadius(0.04);
  source->SetTipRadius(0.1);
  source->Update();
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->DeepCopy(source->GetOutput());
  const Float3 d = normalizeOr(direction, {0, 0, 1});
  const Float3 helper = std::fabs(d.z) < 0.9f ? Float3{0, 0, 1} : Float3{1, 0, 0};
  const Float3 u = normalize(cross(d, helper)), w = cross(d, u);
  vtkPoints* points = poly->GetPoints();
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i) {
    double p[3];
    points->GetPoint(i, p);
    const Float3 q = from + length * (float(p[0]) * d + float(p[1]) * u + float(p[2]) * w);
    points->SetPoint(i, double(q.x), double(q.y), double(q.z));
  }
  return poly;
}

vtkSmartPointer<vtkPolyData> toolSphere(const ToolState& tool) {
  vtkNew<vtkSphereSource> source;
  source->SetCenter(double(tool.centreMm.x), double(tool.centreMm.y), double(tool.centreMm.z));
  source->SetRadius(double(tool.radiusMm));
  source->SetThetaResolution(24);
  source->SetPhiResolution(16);
  source->Update();
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->DeepCopy(source->GetOutput());
  return poly;
}

/// The range of the finite values (a field is NaN where it has no value, e.g. the truth error
/// on hidden vertices); [0, 1] when there are none.
std::array<double, 2> rangeOf(std::span<const float> values) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (float v : values)
    if (std::isfinite(v)) lo = std::min(lo, double(v)), hi = std::max(hi, double(v));
  return lo <= hi ? std::array<double, 2>{lo, hi} : std::array<double, 2>{0.0, 1.0};
}

/// A range symmetric about `centre`, as wide as the largest deviation (diverging maps).
std::array<double, 2> symmetricRange(std::span<const float> values, double centre) {
  double m = 0.0;
  for (float v : values)
    m = std::max(m, std::fabs(double(v) - centre));
  if (m < 1e-6) m = 1e-6;
  return {centre - m, centre + m};
}

float glyphLength(std::span<const Float3> positions) {
  const Bounds3 b = boundsOf(positions);
  return 0.035f * length(b.hi - b.lo);
}

std::size_t strideFor(std::size_t count, std::size_t maxGlyphs) {
  return std::max<std::size_t>(1, (count + maxGlyphs - 1) / maxGlyphs);
}

/// `value` with `digits` decimals (fixed) or significant digits (general).
std::string number(double value, int digits, bool fixed) {
  std::ostringstream text;
  if (fixed) text << std::fixed;
  text << std::setprecision(digits) << value;
  return text.str();
}

std::string timeOf(const OrganSnapshot& f) {
  return ", frame " + std::to_string(f.frame) + " (t = " + number(f.timeS, 3, true) + " s)";
}

Result<void> checkSizes(const OrganSnapshot& f) {
  const std::size_t n = f.nodes.positions.size(), g = f.surface.positions.size(),
                    r = f.render.positions.size();
  const bool ok = f.nodes.strain.size() == f.nodes.springs.size() && f.nodes.stretch.size() == n &&
                  f.surface.stretch.size() == g && f.surface.contactForceN.size() == g &&
                  f.surface.planeNormals.size() == g && f.surface.planeResidualMm.size() == g &&
                  f.surface.normals.size() == g && f.render.tangents.size() == r &&
                  f.render.normals.size() == r && f.render.handednessFlip.size() == r &&
                  f.render.textureStretch.size() == f.render.triangles.size();
  if (!ok)
    return Error{"inspection: the snapshot's arrays do not match its meshes (" + std::to_string(n) +
                 " nodes, " + std::to_string(g) + " surface and " + std::to_string(r) +
                 " render vertices); take it with inspect::snapshotOf"};
  return {};
}

ViewScene springStrain(const OrganSnapshot& f, const ViewSettings& settings) {
  ViewScene s;
  s.data = linesPoly(f.nodes.positions, f.nodes.springs);
  addArray(s.data->GetCellData(), "strain", f.nodes.strain);
  addArray(s.data->GetPointData(), "stretch", f.nodes.stretch);
  addArray(s.data->GetPointData(), "velocity_mm_per_s", f.nodes.velocities);
  s.array = "strain";
  s.cellArray = true;
  s.range = symmetricRange(f.nodes.strain, 0.0);
  s.palette = ViewScene::Palette::CoolWarm;
  s.tubes = f.nodes.springs.size() <= settings.maxTubes;
  s.tubeRadius = 0.15 * double(glyphLength(f.nodes.positions));
  s.barTitle = "spring strain\nL/L0 - 1 (unitless)";
  s.title = "Spring strain per spring" + timeOf(f);
  s.context = surfacePoly(f.surface.positions, f.surface.triangles);
  return s;
}

ViewScene vertexStretch(const OrganSnapshot& f) {
  ViewScene s;
  s.data = surfacePoly(f.surface.positions, f.surface.triangles);
  addArray(s.data->GetPointData(), "stretch", f.surface.stretch);
  addArray(s.data->GetPointData(), "velocity_mm_per_s", f.surface.velocities);
  s.array = "stretch";
  s.range = symmetricRange(f.surface.stretch, 1.0);
  s.palette = ViewScene::Palette::CoolWarm;
  s.barTitle = "stretch per vertex\nmean L/L0 (unitless)";
  s.title = "Stretch per vertex" + timeOf(f);
  return s;
}

ViewScene contactForce(const OrganSnapshot& f) {
  ViewScene s;
  s.data = surfacePoly(f.surface.positions, f.surface.triangles);
  std::vector<float> magnitude(f.surface.contactForceN.size());
  Float3 sum{};
  for (std::size_t i = 0; i < magnitude.size(); ++i) {
    magnitude[i] = length(f.surface.contactForceN[i]);
    sum = sum + f.surface.contactForceN[i];
  }
  addArray(s.data->GetPointData(), "contact_force_N", f.surface.contactForceN);
  addArray(s.data->GetPointData(), "contact_force_magnitude_N", magnitude);
  s.array = "contact_force_magnitude_N";
  s.range = {0.0, std::max(1e-6, rangeOf(magnitude)[1])};
  s.barTitle = "contact force\nper vertex |f| (N)";
  s.title = "Contact force" + timeOf(f);
  if (f.tool.present) {
    const float forceN = length(f.tool.forceN);
    s.overlays.push_back(
        {toolSphere(f.tool),
         {0.55, 0.57, 0.6},
         1.0f,
         1.0f,
         0.3,
         "tool: sphere of radius " + number(double(f.tool.radiusMm), 1, true) + " mm (grey)"});
    if (forceN > 0.0f)
      s.overlays.push_back({arrow(f.tool.centreMm, f.tool.forceN, 3.0f * f.tool.radiusMm),
                            {0.85, 0.1, 0.1},
                            1.0f,
                            1.0f,
                            1.0,
                            "red arrow: force on the tool, |F| = " + number(double(forceN), 4, false) +
                                " N (sum per vertex " + number(double(length(sum)), 4, false) + " N)"});
  }
  return s;
}

ViewScene planeFit(const OrganSnapshot& f, const ViewSettings& settings) {
  ViewScene s;
  s.data = surfacePoly(f.surface.positions, f.surface.triangles);
  addArray(s.data->GetPointData(), "plane_normal", f.surface.planeNormals);
  addArray(s.data->GetPointData(), "plane_offset_mm", f.surface.planeOffsetMm);
  addArray(s.data->GetPointData(), "plane_residual_mm", f.surface.planeResidualMm);
  s.array = "plane_residual_mm";
  s.range = {0.0, std::max(1e-6, rangeOf(f.surface.planeResidualMm)[1])};
  s.barTitle = "plane residual\nRMS distance (mm)";
  s.title = "Local planes (N_S, eq. 14)" + timeOf(f);
  s.overlays.push_back(
      {glyphLines(f.surface.positions, f.surface.planeNormals, glyphLength(f.surface.positions),
                  strideFor(f.surface.positions.size(), settings.maxGlyphs)),
       {0.1, 0.1, 0.1},
       1.5f,
       1.0f,
       1.0,
       "black lines: plane normals N_S"});
  return s;
}

ViewScene tangentFrames(const OrganSnapshot& f, const ViewSettings& settings) {
  const RenderState& r = f.render;
  ViewScene s;
  s.data = surfacePoly(r.positions, r.triangles);
  std::vector<Float3> t(r.tangents.size()), b(r.tangents.size());
  std::vector<float> handedness(r.tangents.size());
  std::vector<Float3> flips;
  for (std::size_t i = 0; i < r.tangents.size(); ++i) {
    t[i] = {r.tangents[i].x, r.tangents[i].y, r.tangents[i].z};
    handedness[i] = r.tangents[i].w;
    b[i] = r.tangents[i].w * cross(r.normals[i], t[i]);  // B = w cross(N, T) (tangent_frames.h)
    if (r.handednessFlip[i] > 0.0f) flips.push_back(r.positions[i]);
  }
  addArray(s.data->GetPointData(), "tangent", r.tangents);
  addArray(s.data->GetPointData(), "bitangent", b);
  addArray(s.data->GetPointData(), "normal", r.normals);
  addArray(s.data->GetPointData(), "handedness", handedness);
  addArray(s.data->GetPointData(), "seam_flip", r.handednessFlip);
  s.array = "handedness";
  s.range = {-1.0, 1.0};
  s.palette = ViewScene::Palette::TwoTone;
  s.barTitle = "handedness w\n(-1 mirrored, +1)";
  s.title = "Tangent frames" + timeOf(f);
  const float len = glyphLength(r.positions);
  const std::size_t stride = strideFor(r.positions.size(), settings.maxGlyphs);
  s.overlays.push_back(
      {glyphLines(r.positions, t, len, stride), {0.85, 0.1, 0.1}, 1.5f, 1.0f, 1.0, "red: T"});
  s.overlays.push_back(
      {glyphLines(r.positions, b, len, stride), {0.1, 0.65, 0.1}, 1.5f, 1.0f, 1.0, "green: B"});
  s.overlays.push_back(
      {glyphLines(r.positions, r.normals, len, stride), {0.1, 0.2, 0.9}, 1.5f, 1.0f, 1.0, "blue: N"});
  s.overlays.push_back(
      {markers(flips),
       {1.0, 0.0, 1.0},
       1.0f,
       7.0f,
       1.0,
       "magenta points: handedness flips at UV seams (" + std::to_string(flips.size()) + ")"});
  return s;
}

ViewScene textureStretch(const OrganSnapshot& f) {
  ViewScene s;
  s.data = surfacePoly(f.render.positions, f.render.triangles);
  addArray(s.data->GetCellData(), "texture_stretch", f.render.textureStretch);
  s.data->GetPointData()->AddArray(
      floatArray("uv", 2, {reinterpret_cast<const float*>(f.render.uvs.data()), f.render.uvs.size() * 2}));
  s.array = "texture_stretch";
  s.cellArray = true;
  s.range = rangeOf(f.render.textureStretch);
  s.barTitle = "texture stretch\n(unitless, 1 = mean)";
  s.title = "Texture-space stretch per triangle" + timeOf(f);
  return s;
}

}  // namespace

Result<ViewScene> buildViewScene(const OrganSnapshot& frame, InspectionView view,
                                 const ViewSettings& settings) {
  if (auto ok = checkSizes(frame); !ok) return ok.error();
  switch (view) {
    case InspectionView::SpringStrain:
      return springStrain(frame, settings);
    case InspectionView::VertexStretch:
      return vertexStretch(frame);
    case InspectionView::ContactForce:
      return contactForce(frame);
    case InspectionView::PlaneFit:
      return planeFit(frame, settings);
    case InspectionView::TangentFrames:
      return tangentFrames(frame, settings);
    case InspectionView::TextureStretch:
      return textureStretch(frame);
  }
  return Error{"inspection: unknown view"};
}

Result<ViewScene> buildTruthErrorScene(const OrganSnapshot& frame, const TruthErrorMap& error) {
  if (error.perRenderVertex.size() != frame.render.positions.size())
    return Error{"truth error view: " + std::to_string(error.perRenderVertex.size()) + " values for " +
                 std::to_string(frame.render.positions.size()) +
                 " render vertices; map the atlas onto every render vertex"};
  ViewScene s;
  s.data = surfacePoly(frame.render.positions, frame.render.triangles);
  addArray(s.data->GetPointData(), "truth_error", error.perRenderVertex);
  s.array = "truth_error";
  s.range = rangeOf(error.perRenderVertex);
  s.barTitle = error.quantity + "\n(" + error.unit + ")";
  s.title = "Error against the path-traced truth" + timeOf(frame);
  return s;
}

}  // namespace tissue::inspect
