#pragma once
/// \file
/// The path-traced truth (tissue::truth) of an organ as the renderer sees it: the renderer's
/// camera, its lights and the organ's current shape for the same frame, and the organ's material
/// file as the truth's layered material. GL-free: nothing here touches the renderer, so a frame
/// rendered with any method can be scored against renderTruth of the same inputs.
///
/// The mapping:
///   camera    render::Camera (look-at, vertical field of view) -> a pinhole TruthCamera with the
///             same basis (glm::lookAt / glm::perspective); the clip planes do not matter
///   lights    render::Light -> TruthLight with radiance = colour * intensity; the truth always
///             traces shadow rays (castsShadows is a renderer's cost switch, not physics)
///   surface   the Blinn-Phong exponent s of render::Material -> Beckmann roughness
///             sqrt(2 / (s + 2)) of the outer surface's glossy reflection (Walter et al. 2007)
///   material  each layer of the material file: sigma_a = sigma_t - sigma_s, sigma_s, g in every
///             band, n = the file's ior; with the subsurface map, its boundary depths per texel
///             (François et al. 2006 §2.1) and the file's depth_scale_mm
/// Lengths in mm, coefficients in mm^-1.

#include <span>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/core/vec_math.h"
#include "tissue/render/scene.h"
#include "tissue/scene/organ_assets.h"
#include "tissue/scene/scene.h"
#include "tissue/truth/path_tracer.h"

namespace tissue::scene {

/// The organ's material file as the truth's material. Until the material reader yields a
/// TruthMaterial itself (scene/truth_material.h), this is the one place that builds it: replace
/// its body by that reader's and keep the signature. Errors, one line naming the file and the
/// key: a layer whose sigma_t or sigma_s is missing, negative or sigma_t < sigma_s
/// ("layers[i].sigma_t"), a file with more layers than its subsurface map bounds, and a layer
/// depth outside the mesh (the deepest boundary, depth_scale_mm times the largest map value,
/// deeper than half the mesh's smallest extent: "depth_scale_mm").
Result<truth::TruthMaterial> truthMaterialOf(const OrganAssets& organ);

/// The renderer's camera as the truth's pinhole camera.
truth::TruthCamera truthCameraOf(const render::Camera& camera);

/// The renderer's lights as the truth's (radiance = colour * intensity, shadows always).
std::vector<truth::TruthLight> truthLightsOf(std::span<const render::Light> lights);

/// Beckmann roughness of the outer surface for the renderer's Blinn-Phong exponent (>= 0).
double roughnessOf(const render::Material& material);

/// One frame as the renderer draws it: the organ at `positionsMm` (one per render vertex of
/// organ.mesh, world mm: the model matrix already applied), seen by `frame.camera` under
/// `frame.lights`, with the glossy lobe of `frame.material`. `settings`' width, height, spp,
/// threads and seed are the caller's; its surfaceRoughness is replaced by roughnessOf(material).
Result<truth::TruthImage> renderTruth(const OrganAssets& organ, std::span<const Float3> positionsMm,
                                      const render::Scene& frame, const truth::PathTraceSettings& settings);

/// The same for organ `organ` of `scene` as of its last render: its camera (Scene::camera), its
/// lights (Scene::renderScene, which stops the lights following the framing, as that call always
/// does), the organ's current shape (its simulation's positions, else its rest shape: a shape
/// given by Scene::setPositions is not visible here) under `model` (object mm to world mm; the
/// Scene does not expose the one given to setTransform).
Result<truth::TruthImage> renderTruth(Scene& scene, OrganId organ, const truth::PathTraceSettings& settings,
                                      const Mat4& model = kIdentity4);

}  // namespace tissue::scene
