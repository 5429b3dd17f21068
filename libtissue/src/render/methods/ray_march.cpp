// The ray-march method's pass: per object, the layer stack and march settings as uniforms,
// the subsurface maps on the method's texture units, one draw (shaders/raymarch/).
#include "ray_march.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "tissue/gl/program.h"

namespace tissue::render {
namespace {

// TISSUE_MAX_LAYERS in shaders/raymarch/march.glsl is 4 * kMaxSubsurfaceMaps + 1 = 9.
static_assert(kMaxSubsurfaceMaps == 2);

// Sets uniforms by name (looked up per object: a handful of lookups is nothing next to the march).
struct Uniforms {
  const gl::GlApi& gl;
  GLuint program;
  GLint at(const std::string& name) const { return gl.GetUniformLocation(program, name.c_str()); }
  void set(const std::string& n, int v) const { gl.Uniform1i(at(n), v); }
  void set(const std::string& n, float v) const { gl.Uniform1f(at(n), v); }
  void set(const std::string& n, Float3 v) const { gl.Uniform3f(at(n), v.x, v.y, v.z); }
};

bool positive(Float3 v) {
  return v.x > 0.0f && v.y > 0.0f && v.z > 0.0f && std::isfinite(v.x + v.y + v.z);
}

// One object's settings, resolved: its maps' GL names and width (texels).
struct ResolvedMaps {
  GLuint maps[kMaxSubsurfaceMaps] = {0, 0};
};

Result<ResolvedMaps> checkObject(const ObjectDraw& d, const RayMarchSettings& s) {
  const std::string where = "renderer: ray-march object " + std::to_string(static_cast<int>(d.objectId) - 1);
  const std::size_t maps = s.subsurfaceMaps.size();
  if (maps < 1 || maps > static_cast<std::size_t>(kMaxSubsurfaceMaps) || s.layers.size() != 4 * maps + 1) {
    return Error{where + " has " + std::to_string(s.layers.size()) + " layers and " + std::to_string(maps) +
                 " subsurface maps; give 1 or 2 RGBA maps and 4N + 1 layers"};
  }
  for (std::size_t i = 0; i < s.layers.size(); ++i) {
    const RayMarchLayer& l = s.layers[i];
    if (!positive(l.sigma_t) || !(l.sigma_s.x >= 0.0f && l.sigma_s.y >= 0.0f && l.sigma_s.z >= 0.0f) ||
        !(std::abs(l.schlickK) < 1.0f)) {
      return Error{where + ", layer " + std::to_string(i) +
                   ": needs sigma_t > 0 and sigma_s >= 0 (mm^-1) and |schlickK| < 1"};
    }
    const auto unit = [](float v) { return v >= 0.0f && v <= 1.0f; };
    const Float3 a = l.multipleAlbedo, t = l.sigmaTr;
    if (!unit(a.x) || !unit(a.y) || !unit(a.z) || !(t.x >= 0.0f && t.y >= 0.0f && t.z >= 0.0f) ||
        !std::isfinite(t.x + t.y + t.z)) {
      return Error{where + ", layer " + std::to_string(i) +
                   ": needs multipleAlbedo in [0, 1] and a finite sigmaTr >= 0 (mm^-1)"};
    }
  }
  if (!(s.ior >= 1.0f) || !std::isfinite(s.ior)) {
    return Error{where + ": ior (the tissue's relative index of refraction) must be finite and >= 1"};
  }
  if (!(s.depthScaleMm > 0.0f) || !(s.uvPerMm > 0.0f) || !(s.depthMaxMm > 0.0f)) {
    return Error{where + ": depthScaleMm, uvPerMm and depthMaxMm must be positive"};
  }
  if (s.adaptive &&
      !(s.cutoff > 0.0f && s.cutoff < 1.0f && s.depthResolutionMm > 0.0f && s.texelsPerStep > 0.0f)) {
    return Error{where + ": adaptive needs 0 < cutoff < 1 and positive depthResolutionMm and texelsPerStep"};
  }
  if (!d.mesh->hasPlanes()) {
    return Error{where +
                 "'s mesh has no planes; give MeshArrays::planes (N_S, d mm per vertex, "
                 "mesh::DeformableSurface::planes()) to createMesh"};
  }
  ResolvedMaps out;
  // The frame resolved the handles (unknown ones are errors there); an empty one is none.
  for (std::size_t i = 0; i < maps; ++i) {
    if (d.methodTextures[i] == 0) {
      return Error{where + "'s subsurface map " + std::to_string(i) +
                   " is no texture; createTexture it with TextureEncoding::LinearData"};
    }
    out.maps[i] = d.methodTextures[i];
  }
  return out;
}

// The layer stack, the march and adaptive quality of one object (march.glsl, raymarch.frag).
void setObjectUniforms(const FrameContext& frame, GLuint program, const RayMarchSettings& s, int texelsWide) {
  const Uniforms u{frame.gl, program};
  const int layers = static_cast<int>(s.layers.size());
  u.set("u_layerCount", layers);
  u.set("u_boundaryCount", static_cast<int>(s.subsurfaceMaps.size()) * 4);
  float sigmaMin = 1e30f;
  for (int i = 0; i < layers; ++i) {
    const RayMarchLayer& l = s.layers[static_cast<std::size_t>(i)];
    const std::string index = std::to_string(i);
    u.set("u_sigmaS[" + index + "]", l.sigma_s);
    u.set("u_sigmaT[" + index + "]", l.sigma_t);
    u.set("u_schlickK[" + index + "]", l.schlickK);
    u.set("u_multipleAlbedo[" + index + "]", l.multipleAlbedo);
    u.set("u_sigmaTr[" + index + "]", l.sigmaTr);
    sigmaMin = std::min({sigmaMin, l.sigma_t.x, l.sigma_t.y, l.sigma_t.z});
  }
  u.set("u_depthScale", s.depthScaleMm);
  u.set("u_uvPerMm", s.uvPerMm);
  // The march (Algorithm 1, eq. 15): beyond -ln(threshold) / sigma_min the attenuation alone
  // is under the threshold, so M_max never lies farther.
  u.set("u_depthMax", s.depthMaxMm);
  u.set("u_tMaxCap", s.attenuationThreshold > 0.0f ? -std::log(s.attenuationThreshold) / sigmaMin : 1e30f);
  u.set("u_threshold", s.attenuationThreshold);
  u.set("u_minCosView", s.minCosView);
  u.set("u_samples", std::clamp(s.samples, 1, 256));
  u.set("u_jitter", s.jitter ? 1 : 0);
  frame.gl.Uniform1ui(u.at("u_seed"), s.seed);
  u.set("u_viewportHeight", frame.height);
  u.set("u_radianceScale", s.radianceScale);
  // The surface (raymarch.frag: François et al. 2006 §3, Norberg 2010 §2.2.2).
  u.set("u_ior", s.ior);
  u.set("u_specularOn", s.specular ? 1 : 0);
  // Adaptive quality.
  u.set("u_minSamples", std::clamp(s.minSamples, 1, 256));
  u.set("u_maxSamples", std::clamp(s.maxSamples, 1, 256));
  u.set("u_depthResolution", s.depthResolutionMm);
  u.set("u_texelsPerStep", s.texelsPerStep);
  u.set("u_cutoff", s.cutoff);
  u.set("u_sigmaMin", sigmaMin);
  u.set("u_texelMm", 1.0f / (s.uvPerMm * static_cast<float>(std::max(texelsWide, 1))));
  const float fov = frame.scene.camera.verticalFovDeg * 3.14159265f / 180.0f;
  u.set("u_pixelAngle", 2.0f * std::tan(0.5f * fov) / static_cast<float>(frame.height));
}

}  // namespace

Result<RayMarchMethod> RayMarchMethod::create(const gl::GlApi& gl, const gl::ShaderLibrary& library) {
  RayMarchMethod m;
  for (const int adaptive : {0, 1}) {
    for (const int show : {0, 1}) {
      std::vector<gl::ShaderDefine> defines;
      if (adaptive) defines.push_back({"TISSUE_ADAPTIVE", "1"});
      if (show) defines.push_back({"TISSUE_SHOW_SAMPLES", "1"});
      auto program =
          gl::buildProgram(gl, library, {"common/surface.vert", "raymarch/raymarch.frag", defines});
      if (!program) return program.error();
      const GLuint id = program->id();
      gl.UseProgram(id);
      gl.Uniform1i(gl.GetUniformLocation(id, "u_baseColor"), kUnitBaseColor);
      gl.Uniform1i(gl.GetUniformLocation(id, "u_normalMap"), kUnitNormalMap);
      gl.Uniform1i(gl.GetUniformLocation(id, "u_subsurface0"), kUnitMethod0);
      gl.Uniform1i(gl.GetUniformLocation(id, "u_subsurface1"), kUnitMethod0 + 1);
      m.m_programs[adaptive][show] = std::move(*program);
    }
  }
  return m;
}

Result<void> RayMarchMethod::draw(const FrameContext& frame, std::span<const ObjectDraw> objects) const {
  std::vector<ResolvedMaps> maps;
  for (const ObjectDraw& d : objects) {
    auto resolved = checkObject(d, std::get<RayMarchSettings>(d.object->method));
    if (!resolved) return resolved.error();
    maps.push_back(*resolved);
  }
  const gl::GlApi& g = frame.gl;
  // No glFinish here: a host's frame must not stall. Benchmarks time the pass to completion with
  // RendererSettings::finishPasses (llvmpipe rasterises lazily, so issuing alone times nothing).
  return frame.passes.run("ray-march", [&]() -> Result<void> {
    beginGeometryPass(frame);
    for (std::size_t i = 0; i < objects.size(); ++i) {
      const ObjectDraw& d = objects[i];
      const auto& s = std::get<RayMarchSettings>(d.object->method);
      const GLuint program = m_programs[s.adaptive ? 1 : 0][s.showSamples ? 1 : 0].id();
      setFrameUniforms(frame, program);
      GLint texelsWide = 1;
      for (int m = 0; m < kMaxSubsurfaceMaps; ++m) {
        g.ActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + kUnitMethod0 + m));
        g.BindTexture(GL_TEXTURE_2D, maps[i].maps[m] ? maps[i].maps[m] : maps[i].maps[0]);
        if (m == 0) g.GetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &texelsWide);
      }
      setObjectUniforms(frame, program, s, texelsWide);
      drawSurface(frame, program, d);
      frame.passes.issued(d.index());  // PassTiming::issued
    }
    return gl::checkGlError(g, "renderer: ray-march pass");
  });
}

}  // namespace tissue::render
