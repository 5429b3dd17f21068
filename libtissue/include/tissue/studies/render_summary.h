#pragma once
/// \file
/// One organ's render in one shading method as tissue-sim render reports it: its assets, the
/// method's settings and the frame's timings, as a JSON object's text.

#include <string>

#include "tissue/render/renderer.h"
#include "tissue/scene/organ_assets.h"
#include "tissue/scene/organ_methods.h"

namespace tissue::studies {

/// method; render_ms and upload_ms (ms, CPU) and passes (loop_report.h's passTimingsJson) of
/// `timings`; material (its file, or "default"), triangles, uvs ("the mesh's own" or the
/// automatic atlas with its chart count), base_color and normal_map (their files, or "");
/// then the settings `method` used from `choices`: separable kernel, taps, rank; texture-space
/// gaussians, map_size, cull, clip, depth_size; ray-march adaptive and max_samples or
/// march_samples, and pass_ms (its pass); parallax layer_depth_mm, refractive_index (the
/// choice, else the material's ior), lightmap_size, lightmap_reduction, blur_radius_mm,
/// blur_passes, cull, clip.
std::string organRenderJson(const scene::OrganAssets& assets, render::ShadingMethod method,
                            const scene::MethodChoices& choices, const render::RenderTimings& timings);

}  // namespace tissue::studies
