#pragma once
/// \file
/// The scene's side of the quality controller (issue 16, quality/controller.h): an organ's view
/// as the controller sees it (the projected footprint of its bounds, distance, view angle), the
/// table options its material offers, and an option as the renderer's method settings. Used by
/// Scene::setBudgetMs and the budget bench. GL: methodOfOption reads the organ's textures.

#include <span>
#include <string>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/core/surface_mesh.h"
#include "tissue/core/vec_math.h"
#include "tissue/quality/controller.h"
#include "tissue/quality/quality_table.h"
#include "tissue/render/renderer.h"
#include "tissue/render/scene.h"
#include "tissue/scene/organ_assets.h"
#include "tissue/scene/organ_methods.h"

namespace tissue::scene {

/// The view of an organ with object bounds `objectBounds` under `model` from `camera` on a
/// `width` x `height` image: the pixels its bounds' projection covers (the rectangle of the
/// eight corners, clipped to the image, times pi / 4 for the ellipse inside it; a box through
/// the near plane covers the image), the distance to its centre (mm) and the angle between the
/// view ray and its thinnest axis (degrees, 90: edge-on).
quality::ObjectView organView(const Bounds3& objectBounds, const Mat4& model, const render::Camera& camera,
                              int width, int height);

/// The same view with the footprint the pixels `mesh` (object space, mm, under `model`) covers:
/// the projected area of its triangles facing one way (the larger of the two ways: a closed
/// surface's front and back each cover its silhouette once, a sheet's one side does), each
/// triangle's corners clamped to the image, and at most the bounds' rectangle. What the quality
/// table's per-pixel costs and the atlas's `organ_pixels` count: the bounds' ellipse overstates a
/// small organ's pixels by 2-4x and the close-up's (cut by the image's edges) by 1.5x, which
/// misweighs objects against each other. At most ~2000 triangles are projected (every k-th, their
/// area times k): a host's frame pays microseconds per organ.
quality::ObjectView organView(const SurfaceMesh& mesh, const Bounds3& objectBounds, const Mat4& model,
                              const render::Camera& camera, int width, int height);

/// The options of `table` whose method `organ` offers (offeredMethods).
std::vector<int> offeredOptions(const quality::QualityTable& table, const OrganAssets& organ);

/// The choices behind an option's setting name (the atlas's names: "preintegrated-17", "6g-opt",
/// "6g-plain", "50", "adaptive-100", "default", "wrap"), over `base`.
Result<MethodChoices> choicesOfSetting(const quality::QualityOption& option, const MethodChoices& base);

/// The option as the renderer's settings for `organ` (the lit fallback with opticalWrap).
Result<render::MethodSettings> methodOfOption(const quality::QualityOption& option, const OrganAssets& organ,
                                              const OrganTextures& textures, const MethodChoices& base);

/// The last frame's measured costs, ms, as the quality controller learns them: each scene
/// object's own passes (render::PassTiming::object), its draws' issue times in passes that draw
/// several objects (PassTiming::issued) with the rest of such a pass (its rasterisation and
/// finish) shared among its objects by `weights` (per object; the covered pixels times the
/// option's per-pixel cost; equal shares where all are 0), and each method's passes of no object
/// (its screen-space passes) by method (ShadingMethod order: "lit", "separable:*",
/// "texture-space*", "ray-march*", "parallax:*"). The rest of the frame is overhead.
struct FramePassCosts {
  std::vector<double> objectMs;  ///< per render::Scene::objects index
  std::vector<double> methodMs;  ///< per ShadingMethod: its passes of no object
};
FramePassCosts framePassCosts(const render::RenderTimings& timings, std::span<const double> weights);

/// What the controller chose for one organ.
struct BudgetChoice {
  std::string method, setting;
  double footprintPx = 0.0;     ///< px
  double predictedMs = 0.0;     ///< ms
  double expectedRelRms = 0.0;  ///< the table's error for its view class
  std::string view;             ///< the atlas frame its view resembles
  double viewAngleDeg = 0.0;    ///< degrees between the view ray and the surface normal (90: edge-on)
  bool fallback = false;        ///< below the footprint threshold: the lit tier (wrap or plain)
  quality::MeshWork mesh;       ///< what its method needs of the mesh each frame
};

}  // namespace tissue::scene
