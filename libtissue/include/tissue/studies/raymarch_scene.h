#pragma once
/// \file
/// An organ ready for ray marching (François et al. 2006), shared by the ray-march render, the
/// benches and the studies: its surface with local planes, the layer stack of its material file
/// with the subsurface map (scene::loadOrganAssets, scene::layerStack), a camera framing it (or
/// a close-up of the poke site), a key and a back light, the poke, a pipeline renderer holding it,
/// and the CPU model's views (tissue::subsurface). Lengths in mm, coefficients in mm^-1.
/// Nothing here reads the environment or prints; the GL parts need the caller's context current.

#include <cstdint>
#include <memory>
#include <vector>

#include "tissue/core/image.h"
#include "tissue/core/result.h"
#include "tissue/core/types.h"
#include "tissue/gl/proc_address.h"
#include "tissue/materials/raymarch_material.h"
#include "tissue/mesh/deformable_surface.h"
#include "tissue/render/renderer.h"
#include "tissue/render/scene.h"
#include "tissue/scene/organ_assets.h"
#include "tissue/subsurface/reference_image.h"

namespace tissue::studies {

/// The display of ray-marched images: radiance times this (RayMarchSettings::radianceScale's
/// default), then the pipeline's tone map at exposure 1; the CPU images use the same.
inline constexpr float kRayMarchRadianceScale = 8.0f;
/// sRGB background of the ray-marched images (render::Scene's default).
inline constexpr Float3 kRayMarchBackground{0.05f, 0.05f, 0.06f};

/// An organ ready for ray marching.
struct RayMarchScene {
  std::unique_ptr<mesh::DeformableSurface> owned;    ///< the surface when the scene loaded it
  const mesh::DeformableSurface* surface = nullptr;  ///< positions, normals, tangents, planes
  materials::RayMarchMaterial material;              ///< the layer stack, its map, uv per mm
  render::Camera camera;                             ///< frames the organ (or the poke site)
  std::vector<subsurface::Light> lights;             ///< a key light and a back light
  std::uint32_t pokeSite = 0;                        ///< geometric vertex the poke pushes
};

/// Loads `source` (scene::loadOrganAssets; the mesh must have its own usable UVs, since the
/// subsurface map is painted on them) for images of `aspect` = width/height. `closeUp` frames a
/// 40 mm wide region around the poke site instead of the whole organ. The planes' neighbourhoods
/// come from the first layer's extinction (François eq. 8). Without the material file the error
/// says ray marching needs one.
Result<RayMarchScene> loadRayMarchScene(scene::OrganSource source, float aspect, bool closeUp);

/// The same for a surface the caller owns and keeps alive (e.g. the demo's poked organ), with
/// the material file and subsurface map of `organ` (its uv per mm measured on `surface`).
Result<RayMarchScene> rayMarchSceneFor(const mesh::DeformableSurface& surface,
                                       const scene::OrganAssets& organ, float aspect, bool closeUp);

/// Pushes the vertices nearest the poke site `depthMm` deep (cosine falloff over `fraction` of
/// the vertices) and updates the surface (planes re-fitted incrementally). Needs a loaded scene
/// (`owned`); errors otherwise.
Result<void> pokeScene(RayMarchScene& scene, double fraction, float depthMm);

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
  /// Renders `width` x `height` pixels; the "ray-march" pass's CPU ms (to completion with
  /// RendererSettings::finishPasses) in `passMs`.
  Result<Image8> render(int width, int height, double* passMs = nullptr);
};

/// Creates the renderer for `scene` on the current context (radiance scale kRayMarchRadianceScale,
/// background kRayMarchBackground, exposure 1).
Result<RayMarchRender> makeRayMarchRender(const RayMarchScene& scene,
                                          const gl::GetProcAddressFn& getProcAddress,
                                          const render::RendererSettings& settings = {});

/// The CPU model's view of the surface and camera.
subsurface::MeshView meshView(const RayMarchScene& scene);
subsurface::PinholeCamera pinholeOf(const render::Camera& camera);

}  // namespace tissue::studies
