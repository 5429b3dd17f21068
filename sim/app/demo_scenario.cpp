#include "demo_scenario.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "deformations.h"
#include "demo_render.h"
#include "material_file.h"
#include "output.h"
#include "raymarch_scene.h"
#include "tissue/core/atomic_file.h"
#include "tissue/core/stopwatch.h"
#include "tissue/inspect/vtk_export.h"
#include "tissue/mesh/deformable_surface.h"
#include "tissue/mesh/load_mesh.h"
#include "tissue/mesh/vertex_normals.h"

namespace tissue::sim_app {
namespace {

/// Running mean of a phase's cost.
struct PhaseTimer {
  double totalMs = 0.0;
  int count = 0;
  void add(double ms) { totalMs += ms, ++count; }
  double meanMs() const { return count ? totalMs / count : 0.0; }
};

std::string markdownReport(const nlohmann::json& r) {
  std::ostringstream md;
  md << "# tissue demo report\n\n"
     << "Mesh `" << r["mesh"].get<std::string>() << "`: " << r["vertices"] << " vertices, " << r["triangles"]
     << " triangles, material `" << r["material"].get<std::string>() << "` (sigma_t " << r["sigma_t_per_mm"]
     << " mm^-1, plane radius " << r["plane_radius_mm"] << " mm).\n\n"
     << "The instrument pokes " << r["poke"]["moved_fraction"] << " of the vertices, "
     << r["poke"]["depth_mm"] << " mm deep, over " << r["frames"]
     << " frames.\n\n## Per-frame phases (mean ms)\n\n| phase | ms |\n|---|---|\n";
  for (const auto& [name, ms] : r["phases_ms"].items())
    md << "| " << name << " | " << ms << " |\n";
  md << "\n## Incremental plane re-fit\n\n"
     << "- planes re-fitted per frame (mean): " << r["refit"]["mean_refitted_fraction"] << " of all\n"
     << "- largest deviation from a full re-fit at the last frame: " << r["refit"]["max_normal_deviation_rad"]
     << " rad, " << r["refit"]["max_offset_deviation_mm"] << " mm\n";
  if (r.contains("render")) {
    md << "\n## Render\n\n"
       << "GL: " << r["render"]["gl_context"].get<std::string>() << ", "
       << r["render"]["gl_renderer"].get<std::string>() << "\n\n";
    for (const auto& img : r["render"]["images"])
      md << "![" << img.get<std::string>() << "](" << img.get<std::string>() << ")\n";
  } else if (r.contains("render_skipped")) {
    md << "\n## Render\n\nskipped: " << r["render_skipped"].get<std::string>() << "\n";
  }
  return md.str();
}

/// Writes the surface with normals, tangents, planes (eq. 14) and displacement as a .vtp file.
Result<void> writeInspection(const mesh::DeformableSurface& surface, const std::filesystem::path& path) {
  const auto& m = surface.mesh();
  std::vector<Float3> planeNormal(m.positions.size());
  std::vector<float> planeOffset(m.positions.size()), displacement(m.positions.size());
  const auto rest = surface.geometricRestPositions();
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    const auto& p = surface.planes()[i];
    planeNormal[i] = {p.x, p.y, p.z};
    planeOffset[i] = p.w;
    const Float3 r = rest[m.geometricIndex[i]], q = m.positions[i];
    displacement[i] =
        std::sqrt((q.x - r.x) * (q.x - r.x) + (q.y - r.y) * (q.y - r.y) + (q.z - r.z) * (q.z - r.z));
  }
  return inspect::writeVtp(path, m.positions, m.triangles,
                           {inspect::fieldOf<Float3>("normal", surface.normals()),
                            inspect::fieldOf<Float4>("tangent_handedness", surface.tangents()),
                            inspect::fieldOf<Float3>("plane_normal", std::span<const Float3>(planeNormal)),
                            {"plane_offset_mm", 1, planeOffset},
                            {"displacement_mm", 1, displacement}});
}

}  // namespace

Result<nlohmann::json> runDemo(const DemoOptions& o) {
  // Setup: the organ, its material, and the shading state that follows it.
  const auto meshPath =
      o.meshFile.empty() ? dataDir() / "meshes" / "liver.obj" : std::filesystem::path(o.meshFile);
  auto loaded = mesh::loadMesh(meshPath, {.requireUvs = true});
  if (!loaded) return loaded.error();
  auto material = readLayeredMaterial(materialFileFor(meshPath));
  if (!material) return material.error();
  const mesh::PlaneFitSettings planeSettings{.sigma_t = material->firstLayerMinSigmaT, .epsilon = 0.01f};
  auto surfaceResult = mesh::DeformableSurface::create(std::move(*loaded), planeSettings);
  if (!surfaceResult) return surfaceResult.error();
  auto& surface = *surfaceResult;
  if (o.frames < 1) return Error{"--frames must be at least 1"};

  const auto rest = surface.geometricRestPositions();
  std::vector<Float3> restNormals(rest.size()), positions(rest.size());
  mesh::computeVertexNormals(rest, surface.geometricTriangles(), restNormals);
  const std::uint32_t site = topVertex(rest);
  DemoRenderer renderer(o.width, o.height);
  nlohmann::json report;
  std::vector<std::string> images;
  if (auto img = renderer.render(surface, *material, o.outDir / "frame_rest.png"); img.ok())
    images.push_back("frame_rest.png");

  // The frame loop: simulate (procedural poke until the simulator lands), update the mesh's
  // shading data, render the last frame.
  PhaseTimer simulate, gather, normals, planes, tangents;
  double refittedFraction = 0.0;
  std::size_t moved = 0;
  for (int frame = 1; frame <= o.frames; ++frame) {
    Stopwatch clock;
    const float t = std::min(1.0f, float(frame) / float(std::max(1, o.frames * 2 / 3)));
    const float depth = o.pokeDepthMm * 0.5f * (1.0f - std::cos(3.14159265f * t));  // ease in and hold
    moved = applyPoke(rest, restNormals, site, o.pokeFraction, depth, positions).size();
    simulate.add(clock.elapsedMs());
    const auto stats = surface.update(positions);
    gather.add(stats.gatherMs), normals.add(stats.normalsMs), planes.add(stats.planesMs),
        tangents.add(stats.tangentsMs);
    refittedFraction += double(stats.refit.refittedPlanes) / double(rest.size()) / o.frames;
  }
  // Check: the incremental planes equal a full re-fit of the final shape.
  std::vector<Float4> incremental(surface.planes().begin(), surface.planes().end());
  surface.refitAllPlanes();
  const auto deviation = mesh::comparePlanes(incremental, surface.planes());
  if (auto img = renderer.render(surface, *material, o.outDir / "frame_poked.png"); img.ok()) {
    images.push_back("frame_poked.png");
    report["render"] = renderer.info();
    report["render"]["images"] = images;
  } else {
    report["render_skipped"] = img.error().message;
  }

  report["raymarch"] = renderPokedOrganRayMarch(surface, material->name, o.outDir, o.width, o.height);

  // Inspection: the poked organ with its shading fields, for ParaView.
  if (auto vtp = writeInspection(surface, o.outDir / "organ_poked.vtp"); !vtp) return vtp.error();
  report["inspection"] = "organ_poked.vtp";

  report["mesh"] = meshPath.string();
  report["material"] = material->name;
  report["vertices"] = rest.size();
  report["triangles"] = surface.triangles().size();
  report["sigma_t_per_mm"] = planeSettings.sigma_t;
  report["plane_radius_mm"] = planeSettings.radiusMm();
  report["frames"] = o.frames;
  report["poke"] = {{"moved_fraction", double(moved) / double(rest.size())}, {"depth_mm", o.pokeDepthMm}};
  report["phases_ms"] = {{"1 simulate (procedural poke)", simulate.meanMs()},
                         {"2 positions in", gather.meanMs()},
                         {"3 normals", normals.meanMs()},
                         {"4 planes (incremental)", planes.meanMs()},
                         {"5 tangent frames", tangents.meanMs()}};
  report["refit"] = {{"mean_refitted_fraction", refittedFraction},
                     {"max_normal_deviation_rad", deviation.maxAngleRad},
                     {"max_offset_deviation_mm", deviation.maxOffsetMm}};
  report["out"] = o.outDir.string();
  if (auto w = writeTextFileAtomic(o.outDir / "report.json", report.dump(2) + "\n"); !w) return w.error();
  if (auto w = writeTextFileAtomic(o.outDir / "report.md", markdownReport(report)); !w) return w.error();
  return report;
}

}  // namespace tissue::sim_app
