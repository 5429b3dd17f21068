#pragma once
/// \file
/// What the ray-marching commands share: an organ of the project's data with its layer stack,
/// camera and lights, and the conversions between the GL-free model (tissue::subsurface) and
/// the GPU renderer (tissue::render::RayMarchRenderer). Lengths in mm.

#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "command.h"
#include "tissue/core/image.h"
#include "tissue/core/result.h"
#include "tissue/mesh/deformable_surface.h"
#include "tissue/render/raymarch_renderer.h"
#include "tissue/render/scene.h"
#include "tissue/subsurface/reference_image.h"

namespace tissue::sim_app {

/// An organ ready for ray marching.
struct RayMarchScene {
  std::unique_ptr<mesh::DeformableSurface> owned;    ///< the surface when the scene loaded it
  const mesh::DeformableSurface* surface = nullptr;  ///< positions, normals, tangents, planes
  subsurface::LayerStack stack;                      ///< data/materials/<stem>.json
  Image8 subsurfaceMap;                              ///< the RGBA map the stack was built from
  float uvPerMm = 0.0f;                              ///< texture units per mm of this mesh
  render::Camera camera;                             ///< frames the organ (or the poke site)
  std::vector<subsurface::Light> lights;             ///< a key light and a back light
  std::uint32_t pokeSite = 0;                        ///< geometric vertex the poke pushes
};

/// Loads `meshFile` (a data/ mesh with a material file) for images of `aspect` = width/height.
/// `closeUp` frames a 40 mm wide region around the poke site instead of the whole organ.
Result<RayMarchScene> loadRayMarchScene(const std::filesystem::path& meshFile, float aspect, bool closeUp);

/// The same for a surface the caller owns and keeps alive (e.g. the demo's poked organ);
/// `stem` names its data/ material and textures.
Result<RayMarchScene> rayMarchSceneFor(const mesh::DeformableSurface& surface, const std::string& stem,
                                       float aspect, bool closeUp);

/// Pushes the vertices nearest the poke site `depthMm` deep (cosine falloff over `fraction` of
/// the vertices) and updates the surface (planes re-fitted incrementally). Needs a loaded scene.
void pokeScene(RayMarchScene& scene, double fraction, float depthMm);

/// The GPU renderer's material and lights.
render::RayMarchMaterial gpuMaterial(const RayMarchScene& scene);
std::vector<render::RayMarchLight> gpuLights(const RayMarchScene& scene);

/// The CPU model's view of the surface and camera.
subsurface::MeshView meshView(const RayMarchScene& scene);
subsurface::PinholeCamera pinholeOf(const render::Camera& camera);

/// Renders `scene` with ray-marched single scattering on a new headless context into `png`
/// (written atomically), `width` x `height` pixels; returns what it did (ms, context).
Result<nlohmann::json> renderRayMarchPng(const RayMarchScene& scene,
                                         const render::RayMarchRenderSettings& settings, int width,
                                         int height, const std::filesystem::path& png);

/// `tissue-sim render --method raymarch`: the whole organ of data/ mesh `meshFile`; prints the
/// result like every command and returns the exit code.
int runRayMarchRender(const std::string& meshFile, const std::string& png, int width, int height, int samples,
                      bool adaptive, const GlobalOptions& global);

/// The demo's ray-marched render of its poked organ (`stem` names the data/ material): the
/// whole organ and a close-up of the poke, adaptive quality, into `outDir`.
/// Returns the report entry (images written, or why they were skipped).
nlohmann::json renderPokedOrganRayMarch(const mesh::DeformableSurface& surface, const std::string& stem,
                                        const std::filesystem::path& outDir, int width, int height);

/// A renderer for the scene (mesh and material uploaded); the context must be current.
Result<render::RayMarchRenderer> makeRayMarchRenderer(const RayMarchScene& scene,
                                                      const gl::GetProcAddressFn& getProcAddress);

}  // namespace tissue::sim_app
