#pragma once
/// \file
/// What the ray-marching commands share: an organ of the project's data with its layer stack,
/// camera and lights, and the conversions between the GL-free model (tissue::subsurface) and
/// the render pipeline's ray-march method (render::RayMarchSettings). Lengths in mm.

#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "command.h"
#include "tissue/core/image.h"
#include "tissue/core/result.h"
#include "tissue/materials/raymarch_material.h"
#include "tissue/mesh/deformable_surface.h"
#include "tissue/render/renderer.h"
#include "tissue/render/scene.h"
#include "tissue/subsurface/reference_image.h"

namespace tissue::sim_app {

/// The display of ray-marched images: radiance times this (RayMarchSettings::radianceScale's
/// default), then the pipeline's tone map at exposure 1; the CPU images use the same.
inline constexpr float kRayMarchRadianceScale = 8.0f;
/// sRGB background of the ray-marched images (render::Scene's default).
inline constexpr Float3 kRayMarchBackground{0.05f, 0.05f, 0.06f};

/// An organ ready for ray marching.
struct RayMarchScene {
  std::unique_ptr<mesh::DeformableSurface> owned;    ///< the surface when the scene loaded it
  const mesh::DeformableSurface* surface = nullptr;  ///< positions, normals, tangents, planes
  materials::RayMarchMaterial material;              ///< data/materials/<stem>.json, its map, uv per mm
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

/// The scene's lights as the pipeline's point lights (colour = radiance, intensity 1, no shadows).
std::vector<render::Light> pipelineLights(const RayMarchScene& scene);

/// `march` (the march and adaptive-quality fields) with the scene's material: its layers (Schlick
/// k from g), the uploaded subsurface map `map`, depth scale and uvPerMm
/// (materials::withRayMarchMaterial).
render::RayMarchSettings withMaterial(render::RayMarchSettings march, const RayMarchScene& scene,
                                      render::TextureHandle map);

/// A pipeline renderer holding the scene's organ (planes included) and subsurface map, and a
/// render::Scene with the organ as its one ray-march object. Needs the context current.
struct RayMarchRender {
  render::Renderer renderer;
  render::MeshHandle mesh;
  render::TextureHandle map;
  render::Scene scene;
  /// The organ's method settings.
  render::RayMarchSettings& settings() { return std::get<render::RayMarchSettings>(scene.objects[0].method); }
  /// Sets the march and adaptive-quality fields of `march`, keeping the material.
  void setMarch(const render::RayMarchSettings& march);
  /// Re-uploads the surface's positions, normals, tangents and planes (all vertices).
  Result<void> upload(const mesh::DeformableSurface& surface);
  /// Renders `width` x `height` pixels; the "ray-march" pass's CPU ms (to completion) in `passMs`.
  Result<Image8> render(int width, int height, double* passMs = nullptr);
};

/// Creates the renderer for `scene` on the current context.
Result<RayMarchRender> makeRayMarchRender(const RayMarchScene& scene,
                                          const gl::GetProcAddressFn& getProcAddress,
                                          const render::RendererSettings& settings = {});

/// The CPU model's view of the surface and camera.
subsurface::MeshView meshView(const RayMarchScene& scene);
subsurface::PinholeCamera pinholeOf(const render::Camera& camera);

/// Renders `scene` with ray-marched single scattering on a new headless context into `png`
/// (written atomically), `width` x `height` pixels; returns what it did (ms, context).
/// `march` gives the march and adaptive-quality fields (the material is the scene's).
Result<nlohmann::json> renderRayMarchPng(const RayMarchScene& scene, const render::RayMarchSettings& march,
                                         int width, int height, const std::filesystem::path& png);

/// `tissue-sim render --method raymarch`: the whole organ of data/ mesh `meshFile`; prints the
/// result like every command and returns the exit code.
int runRayMarchRender(const std::string& meshFile, const std::string& png, int width, int height, int samples,
                      bool adaptive, const GlobalOptions& global);

/// The demo's ray-marched render of its poked organ (`stem` names the data/ material): the
/// whole organ and a close-up of the poke, adaptive quality, into `outDir`.
/// Returns the report entry (images written, or why they were skipped).
nlohmann::json renderPokedOrganRayMarch(const mesh::DeformableSurface& surface, const std::string& stem,
                                        const std::filesystem::path& outDir, int width, int height);

}  // namespace tissue::sim_app
