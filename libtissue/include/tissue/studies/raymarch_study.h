#pragma once
/// \file
/// Where ray-marched subsurface texture mapping (François et al. 2006) fails: the plane
/// approximation of the light's entry point (eq. 14's fitted planes) and a march of few jittered
/// samples, each against the mesh-mode march (the light enters through the actual mesh) with
/// many samples, in display RMS over all covered pixels, the grazing ones (N.V < 0.3) and the
/// frontal ones (N.V >= 0.7). Computed with the CPU model (tissue::subsurface), which the GL
/// tests show equals the shader. GL-free (the cases' organs load through raymarch_scene.h).

#include <functional>
#include <span>
#include <string>
#include <vector>

#include "tissue/core/image.h"
#include "tissue/core/result.h"
#include "tissue/scene/organ_assets.h"
#include "tissue/studies/report.h"
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

/// One case of `tissue-sim raymarch-study`: a mesh (by file stem), poked or not.
struct RayMarchStudyCase {
  const char* name;
  const char* mesh;   ///< file stem: the caller's organ source names the files
  float pokeDepthMm;  ///< mm; 0 = rest shape
  const char* what;
};

/// The study's cases: the control (a nearly flat dome), the liver at rest and poked 8 and 16 mm
/// deep (large deformation), and the bowel tube (high curvature).
inline constexpr RayMarchStudyCase kRayMarchStudyCases[] = {
    {"patch", "patch", 0.0f, "nearly flat (250 mm dome), rest shape"},
    {"liver", "liver", 0.0f, "liver top, rest shape"},
    {"liver_poke8", "liver", 8.0f, "liver poked 8 mm deep"},
    {"liver_poke16", "liver", 16.0f, "liver poked 16 mm deep (large deformation)"},
    {"tube", "tube", 0.0f, "bowel tube, radius 8-12 mm (high curvature)"},
};

/// One case's errors.
struct RayMarchCaseResult {
  std::string name, what;
  RayMarchErrors planes, few;
};

/// Every case and the report: raymarch_study.json (width, height, reference_samples, cases [case,
/// what, plane_rms, plane_rms_grazing, plane_rms_frontal, samples10_rms, samples10_rms_grazing,
/// samples10_rms_frontal]), raymarch_study.md, raymarch_study.csv (one row per case), and with
/// `images` per case raymarch_fail_<case>_reference.png, _10samples.png and _plane_error_x8.png.
struct RayMarchStudyResult {
  std::vector<RayMarchCaseResult> cases;
  StudyOutput output;
};

/// Runs every case of kRayMarchStudyCases: the organ of `organSource(mesh stem)` (a mesh with its
/// material file and subsurface map, closed-up on the poke site), poked 2% of its vertices deep,
/// through studyRayMarch. Errors name the case.
Result<RayMarchStudyResult> runRayMarchStudy(
    const std::function<scene::OrganSource(const std::string&)>& organSource,
    const RayMarchStudyConfig& config = {}, bool images = false);

}  // namespace tissue::studies
