#pragma once
/// \file
/// Where ray-marched subsurface texture mapping (François et al. 2006) fails: the plane
/// approximation of the light's entry point (eq. 14's fitted planes) and a march of few jittered
/// samples, each against the mesh-mode march (the light enters through the actual mesh) with
/// many samples, in display RMS over all covered pixels, the grazing ones (N.V < 0.3) and the
/// frontal ones (N.V >= 0.7). Computed with the CPU model (tissue::subsurface), which the GL
/// tests show equals the shader. GL-free.

#include <span>

#include "tissue/core/image.h"
#include "tissue/subsurface/reference_image.h"

namespace tissue::studies {

struct RayMarchStudyConfig {
  int width = 120, height = 90;            ///< pixels
  int referenceSamples = 100;              ///< samples of the reference and of the plane-mode image
  int fewSamples = 10;                     ///< samples of the jittered few-sample image
  float radianceScale = 8.0f;              ///< display exposure (the pipeline's ray-march radiance scale)
  Float3 background{0.05f, 0.05f, 0.06f};  ///< sRGB 0..1, uncovered pixels
};

/// Display RMS (full scale 0..1) against the reference; -1 where no pixel falls in the band.
struct RayMarchErrors {
  double all = 0.0, grazing = 0.0, frontal = 0.0;
};

struct RayMarchStudy {
  RayMarchErrors planes;                    ///< plane entry, referenceSamples
  RayMarchErrors few;                       ///< plane entry, fewSamples, jittered
  Image8 reference, planesImage, fewImage;  ///< the display images (RGBA8)
};

RayMarchStudy studyRayMarch(const subsurface::MeshView& mesh, const subsurface::LayerStack& stack,
                            std::span<const subsurface::Light> lights,
                            const subsurface::PinholeCamera& camera, const RayMarchStudyConfig& config = {});

/// Display RMS of `a` against `b` over the pixels `reference` covers whose N.V lies in
/// [lo, hi); -1 when there are none.
double displayRmsWhere(const Image8& a, const Image8& b, const subsurface::RadianceImage& reference, float lo,
                       float hi);

/// |a - b| x `gain` per RGB channel (clamped to 255), alpha 255: where an approximation goes wrong.
Image8 differenceImage(const Image8& a, const Image8& b, int gain = 8);

}  // namespace tissue::studies
