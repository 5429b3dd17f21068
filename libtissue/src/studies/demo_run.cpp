// The main job (demo_run.h): the default scenario through the trainee's loop, its snapshots in
// every method, the scene a host embeds, and the report.
#include "tissue/studies/demo_run.h"

#include <cstdio>
#include <memory>
#include <optional>
#include <sstream>

#include "demo_renders.h"
#include "json_text.h"
#include "loop_detail.h"
#include "tissue/core/atomic_file.h"
#include "tissue/core/image.h"
#include "tissue/inspect/vtk_export.h"
#include "tissue/scenario/scenario_run.h"
#include "tissue/scene/organ_loop.h"
#include "tissue/scene/session.h"
#include "tissue/scene/surface_inspection.h"
#include "tissue/studies/loop_report.h"

namespace tissue::studies {
namespace {

/// `x` as a C++ stream writes it (6 significant digits): the Markdown's rounded figures.
std::string streamed(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

/// The contact force summary, and the force every 50 frames.
void instrumentMarkdown(const nlohmann::json& i, std::ostringstream& md) {
  md << "## Instrument\n\n"
     << "- frames: " << i["frames"] << ", frames with NaN: " << i["nan_frames"]
     << ", divergence events: " << i["divergence_events"] << "\n"
     << "- contact force on the tool: max " << threeDigits(i["max_contact_force_N"].get<double>())
     << " N, mean " << threeDigits(i["mean_contact_force_N"].get<double>())
     << " N (every frame in report.json and frames.csv)\n"
     << "- deepest push " << threeDigits(i["max_push_N"].get<double>())
     << " N, strongest pull while grasping " << threeDigits(i["max_pull_N"].get<double>()) << " N\n"
     << "- deepest poke at frame " << i["poked_frame"] << ", strongest lift at frame " << i["lifted_frame"]
     << "\n\n";
  Table forces{.header = {"frame", "F_x (N)", "F_y (N)", "F_z (N)"}, .rows = {}};
  const auto& perFrame = i["contact_force_N_per_frame"];
  for (std::size_t f = 0; f < perFrame.size(); f += 50)
    forces.rows.push_back({std::to_string(f), streamed(threeDigits(perFrame[f][0].get<double>())),
                           streamed(threeDigits(perFrame[f][1].get<double>())),
                           streamed(threeDigits(perFrame[f][2].get<double>()))});
  md << markdownTable(forces);
}

/// report.md: the run, the instrument, the loop's phases (`phases`, loopPhasesTable), the re-fit, the render.
std::string markdownReport(const nlohmann::json& r, const Table& phases) {
  std::ostringstream md;
  md << "# tissue demo report\n\n"
     << "Mesh `" << r["mesh"].get<std::string>() << "`: " << r["vertices"] << " vertices, " << r["triangles"]
     << " triangles, material `" << r["material"].get<std::string>() << "` (sigma_t " << r["sigma_t_per_mm"]
     << " mm^-1, plane radius " << r["plane_radius_mm"] << " mm).\n\n"
     << "Scenario `" << r["scenario"].get<std::string>() << "` (" << r["springs"]
     << " springs): a sphere pokes, grasps, lifts and releases the organ over " << r["frames"]
     << " frames.\n\n";
  instrumentMarkdown(r["instrument"], md);
  md << "\n## The frame loop: simulate, mesh, upload, render, every frame (ms)\n\n" << markdownTable(phases);
  if (r.contains("sequence") && r["sequence"].contains("image"))
    md << "\nEvery " << r["image_every"] << " frames: ![sequence]("
       << r["sequence"]["image"].get<std::string>() << ")\n";
  md << "\n## Incremental plane re-fit\n\n"
     << "- planes re-fitted per frame (mean): " << r["refit"]["mean_refitted_fraction"] << " of all\n"
     << "- largest deviation from a full re-fit at the last frame: " << r["refit"]["max_normal_deviation_rad"]
     << " rad (stated tolerance " << r["refit"]["tolerance_rad"] << " rad), "
     << r["refit"]["max_offset_deviation_mm"] << " mm\n";
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

/// The demo's scenes on one headless context: the loop's (the scenario's organ, drawn as a
/// trainee's frame) and the snapshots' (the same organ static, 4x MSAA, every method).
struct DemoSetup {
  std::unique_ptr<context::GlContext> context;  ///< none: simulation only (render_skipped)
  std::optional<scene::Scene> loop, snapshots;
  std::optional<mesh::DeformableSurface> surface;  ///< the snapshots' shape, for the checks
  const scene::OrganAssets& organ() const { return loop->assets(0); }
  const scene::OrganLoop& organLoop() const { return *loop->loop(0); }
};

Result<DemoSetup> setUp(const DemoConfig& o, const scene::SceneSettings& settings, nlohmann::json& report) {
  if (o.frames < 0) return Error{"DemoConfig::frames must be at least 1 (0: the scenario's)"};
  DemoSetup d;
  if (auto context = detail::offscreenContext(settings, o.logContext); context)  // the scenes draw offscreen
    d.context = std::move(*context);
  else
    report["render_skipped"] = context.error().message;  // simulate and update the mesh all the same
  scene::SceneSettings loopSettings = settings;
  loopSettings.meshWorkFollowsMethod = false;  // the report checks the loop's planes against a full re-fit
  auto loop = detail::makeLoopScene(d.context.get(), loopSettings);
  if (!loop) return loop.error();
  d.loop.emplace(std::move(*loop));
  const scene::OrganDesc organ{.mesh = o.meshFile,
                               .scenario = o.scenarioFile.empty()
                                               ? o.dataDir / "scenarios" / "liver_poke_grasp.json"
                                               : o.scenarioFile};
  if (auto added = d.loop->addOrgan(organ); !added) return added.error();
  const scenario::Scenario& sc = d.organLoop().run().scenario();
  auto surface = mesh::DeformableSurface::create(d.organ().mesh, d.organ().planes);
  if (!surface) return surface.error();
  d.surface.emplace(std::move(*surface));
  if (!d.context) return d;
  scene::SceneSettings snapshotSettings = settings;
  snapshotSettings.renderer.samples = 4;
  snapshotSettings.renderer.finishPasses = true;  // each pass timed to its end
  auto snapshots = scene::Scene::create(d.context->procAddressFunction(), snapshotSettings);
  if (!snapshots) return snapshots.error();
  d.snapshots.emplace(std::move(*snapshots));
  auto added = d.snapshots->addOrgan({.mesh = o.meshFile.empty() ? sc.mesh : o.meshFile,
                                      .material = d.organ().material.file,
                                      .meshScaleToMm = float(sc.meshScaleToMm)});
  if (!added) return added.error();
  return d;
}

/// The images in `files` tiled `columns` per row, each shrunk `shrink` times, into `png`.
/// Returns the file name and the panels, or why it was skipped.
nlohmann::json writeMontage(const std::filesystem::path& dir, const std::vector<std::string>& files,
                            const std::string& png, int columns, int shrink) {
  std::vector<Image8> images;
  for (const auto& f : files) {
    auto image = readImage(dir / f, 4);
    if (!image) return {{"skipped", f + ": " + image.error().message}};
    images.push_back(std::move(*image));
  }
  auto tiled = tileImages(images, columns, shrink);
  if (!tiled) return {{"skipped", tiled.error().message}};
  if (auto r = writePng(dir / png, *tiled); !r) return {{"skipped", r.error().message}};
  return {{"image", png}, {"panels", files}};
}

/// The snapshot organ in the state `positions`, lit, into `png`.
void renderSnapshot(DemoSetup& d, std::span<const Float3> positions, const std::filesystem::path& png,
                    const DemoConfig& o, std::vector<std::string>& images, nlohmann::json& report) {
  d.surface->update(positions);
  auto ok = d.snapshots->setPositions(0, positions);
  if (ok) ok = d.snapshots->renderPng(png, o.width, o.height);
  if (ok)
    images.push_back(png.filename().string());
  else
    report["render_skipped"] = ok.error().message;
}

/// What the frame loop keeps: the library's record, and the images written every `imageEvery` frames.
struct LoopResult {
  scene::LoopRecord record;
  std::vector<std::string> sequence;  ///< frames/frame_NNNN.png, in order
};

/// The trainee's loop, headless: every frame simulates, updates the mesh, uploads and renders
/// (Scene::advance, the library's loop); every `imageEvery` frames the rendered image is written.
Result<LoopResult> runFrames(DemoSetup& d, const DemoConfig& o) {
  LoopResult r;
  Image8 image;
  Image8* target = d.context ? &image : nullptr;
  const int frames = o.frames > 0 ? o.frames : d.organLoop().run().scenario().frames;
  std::optional<scene::SessionRecorder> recorder;
  if (!o.recordSession.empty()) recorder.emplace(d.organLoop());
  for (int frame = 0; frame < frames; ++frame) {
    auto f = d.loop->advance(0, {}, target, o.loopWidth, o.loopHeight);
    if (!f) return f.error();
    r.record.add(*f, d.organLoop());  // and the snapshots: the hardest push and the hardest pull
    if (recorder) recorder->recordFrame(d.organLoop());
    if (target && (frame + 1) % o.imageEvery == 0) {
      char name[32];
      std::snprintf(name, sizeof name, "frame_%04d.png", frame + 1);
      if (auto w = writePng(o.outDir / "frames" / name, image); !w) return w.error();
      r.sequence.push_back(std::string("frames/") + name);
    }
  }
  if (recorder)
    if (auto w = scene::saveSession(recorder->session(), o.recordSession); !w) return w.error();
  return r;
}

}  // namespace

Result<DemoRun> runDemo(const DemoConfig& o, const scene::SceneSettings& settings) {
  // Setup: the organ, its material, the scenes that move and draw it, and the snapshots' surface.
  nlohmann::json report;
  auto setup = setUp(o, settings, report);
  if (!setup) return setup.error();
  DemoSetup& d = *setup;
  std::vector<std::string> images;
  const auto rest = d.surface->geometricRestPositions();
  const std::vector<Float3> restPositions(rest.begin(), rest.end());

  // The frame loop: simulate, mesh update, upload, render, every frame (named, timed phases).
  auto loop = runFrames(d, o);
  if (!loop) return loop.error();
  const scene::LoopRecord& r = loop->record;
  const scene::OrganLoop& organLoop = d.organLoop();
  // Check: the loop's incremental planes against a full re-fit of the final shape.
  d.surface->update(organLoop.geometricPositions());
  d.surface->refitAllPlanes();
  const auto deviation = mesh::comparePlanes(organLoop.surface().planes(), d.surface->planes());
  if (auto w = writeTextFileAtomic(o.outDir / "frames.csv", scenario::framesCsv(r.frames)); !w)
    return w.error();
  if (!loop->sequence.empty())
    report["sequence"] = writeMontage(o.outDir, loop->sequence, "frame_sequence.png", 5, 2);

  // Snapshots: rest, the deepest poke, the strongest lift, rendered at full quality; then the
  // poked organ (its shape after the last snapshot) in the four subsurface methods, the one
  // object switched between them at run time, and side by side.
  if (d.snapshots) {
    const std::vector<Float3>& poked = r.pokedPositions.empty() ? restPositions : r.pokedPositions;
    renderSnapshot(d, restPositions, o.outDir / "frame_rest.png", o, images, report);
    if (!r.liftedPositions.empty())
      renderSnapshot(d, r.liftedPositions, o.outDir / "frame_lifted.png", o, images, report);
    renderSnapshot(d, poked, o.outDir / "frame_poked.png", o, images, report);
    if (!report.contains("render_skipped")) {
      const auto& i = d.context->info();
      const auto& t = d.snapshots->renderer().lastTimings();
      report["render"] = {{"gl_context", i.backend},
                          {"gl_platform", i.platform},
                          {"gl_vendor", i.vendor},
                          {"gl_renderer", i.renderer},
                          {"gl_version", i.version},
                          {"last_frame_ms", {{"upload_cpu", t.uploadCpuMs}, {"total_cpu", t.totalCpuMs}}},
                          {"last_frame_passes", detail::passTimings(t)},
                          {"images", images}};
    }
    scene::Scene& s = *d.snapshots;
    report["render_separable"] =
        detail::renderSubsurface(s, o.outDir / "frame_poked_separable.png", o.width, o.height, false);
    report["texture_space"] =
        detail::renderSubsurface(s, o.outDir / "frame_poked_texture_space.png", o.width, o.height, true);
    report["parallax"] = detail::renderParallax(s, o.outDir / "frame_poked_parallax.png", o.width, o.height);
    report["raymarch"] = detail::renderRayMarch(s, *d.surface, o.outDir, o.width, o.height);
    // The scene a host embeds (scene::Scene on its own context, as the C API and the example
    // hosts use it): the simulated liver and a turned, scaled static copy, poked by a host.
    report["embedded_scene"] = detail::renderEmbeddedScene(settings, o.dataDir, o.outDir, o.width, o.height);
    (void)d.context->makeCurrent();  // the demo's scenes are freed with their context current
    report["methods"] = writeMontage(o.outDir,
                                     {"frame_poked_separable.png", "frame_poked_texture_space.png",
                                      "frame_poked_raymarch.png", "frame_poked_parallax.png"},
                                     "frame_poked_methods.png", 2, 1);
  }

  // Inspection: the poked organ with its shading fields, for ParaView (a VTK export: a build
  // without VTK, TISSUE_WITH_VTK=OFF, writes none and says so in the report).
  if (inspect::builtWithVtk()) {
    if (auto vtp = scene::writeSurfaceVtp(*d.surface, o.outDir / "organ_poked.vtp"); !vtp) return vtp.error();
    report["inspection"] = "organ_poked.vtp";
  } else {
    report["inspection"] = nullptr;
    report["inspection_skipped"] = "built without VTK (TISSUE_WITH_VTK=OFF): no organ_poked.vtp";
  }

  const scenario::ScenarioRun& run = organLoop.run();
  report["mesh"] = run.scenario().mesh.string();
  report["scenario"] = run.scenario().file.string();
  report["material"] = d.organ().material.name;
  report["vertices"] = rest.size();
  report["triangles"] = d.surface->triangles().size();
  report["springs"] = run.simulator().system().springs.size();
  report["simulated_nodes"] = run.simulator().state().x.size();
  report["sigma_t_per_mm"] = d.organ().planes.sigma_t;
  report["plane_radius_mm"] = d.organ().planes.radiusMm();
  report["frames"] = r.frames.size();
  report["image_every"] = o.imageEvery;
  report["loop_image_size"] = {o.loopWidth, o.loopHeight};
  report["instrument"] = detail::instrument(r);
  report["phases_ms"] = detail::loopPhases(r.phases);
  report["refit"] = {{"mean_refitted_fraction", r.meanRefittedFraction()},
                     {"tolerance_rad", organLoop.surface().planeRefit().maxNormalErrorRad},
                     {"max_normal_deviation_rad", deviation.maxAngleRad},
                     {"max_offset_deviation_mm", deviation.maxOffsetMm}};
  report["out"] = o.outDir.string();
  DemoRun out;
  out.report.add("report.json", detail::jsonText(report));
  out.report.add("report.md", markdownReport(report, loopPhasesTable(r.phases)));
  if (auto w = writeReport(o.outDir, out.report); !w) return w.error();
  report["instrument"].erase("contact_force_N_per_frame");  // stdout: the summary; files: every frame
  out.json = report.dump();
  return out;
}

}  // namespace tissue::studies
