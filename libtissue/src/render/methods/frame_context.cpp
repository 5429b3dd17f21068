#include "frame_context.h"

#include <glm/gtc/type_ptr.hpp>

#include "tissue/gl/program.h"

namespace tissue::render {

void beginGeometryPass(const FrameContext& frame) {
  const gl::GlApi& g = frame.gl;
  g.BindFramebuffer(GL_FRAMEBUFFER, frame.targets.geometryFramebuffer());
  g.Viewport(0, 0, frame.width, frame.height);
  g.Disable(GL_BLEND);
  g.Disable(GL_SCISSOR_TEST);
  g.Disable(GL_FRAMEBUFFER_SRGB);  // linear targets; post/tonemap.frag encodes sRGB itself
  g.Enable(GL_DEPTH_TEST);
  g.DepthFunc(GL_LESS);
  g.DepthMask(GL_TRUE);
  g.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  g.Enable(GL_CULL_FACE);
  g.CullFace(GL_BACK);
  g.FrontFace(GL_CCW);
  if (frame.targets.samples() > 1) g.Enable(GL_MULTISAMPLE);
}

void setFrameUniforms(const FrameContext& frame, GLuint program) {
  const gl::GlApi& g = frame.gl;
  auto at = [&](const char* name) { return g.GetUniformLocation(program, name); };
  g.UseProgram(program);
  g.UniformMatrix4fv(at("u_viewProjection"), 1, GL_FALSE, glm::value_ptr(frame.viewProjection));
  const Float3 eye = frame.scene.camera.eye;
  g.Uniform3f(at("u_cameraPosition"), eye.x, eye.y, eye.z);
  g.Uniform3f(at("u_cameraForward"), frame.cameraForward.x, frame.cameraForward.y, frame.cameraForward.z);
  setLightUniforms(g, program, frame.lights, kUnitShadowMaps);
  g.ActiveTexture(GL_TEXTURE0 + kUnitShadowMaps);
  g.BindTexture(GL_TEXTURE_2D_ARRAY, frame.shadowMaps);
}

void setModelUniforms(const gl::GlApi& gl, GLuint program, const ModelTransform& transform) {
  gl.UniformMatrix4fv(gl.GetUniformLocation(program, "u_model"), 1, GL_FALSE,
                      glm::value_ptr(transform.model));
  gl.UniformMatrix3fv(gl.GetUniformLocation(program, "u_normalMatrix"), 1, GL_FALSE,
                      glm::value_ptr(transform.normalMatrix));
}

void drawSurface(const FrameContext& frame, GLuint program, const ObjectDraw& draw) {
  const gl::GlApi& g = frame.gl;
  auto at = [&](const char* name) { return g.GetUniformLocation(program, name); };
  setModelUniforms(g, program, draw.transform);
  const Material& m = draw.object->material;
  g.Uniform3f(at("u_ambient"), m.ambient.x, m.ambient.y, m.ambient.z);
  g.Uniform1f(at("u_specular"), m.specular);
  g.Uniform1f(at("u_shininess"), m.shininess);
  g.Uniform1f(at("u_objectId"), draw.objectId);
  g.ActiveTexture(GL_TEXTURE0 + kUnitBaseColor);
  g.BindTexture(GL_TEXTURE_2D, draw.baseColor);
  g.ActiveTexture(GL_TEXTURE0 + kUnitNormalMap);
  g.BindTexture(GL_TEXTURE_2D, draw.normalMap);
  g.BindVertexArray(draw.mesh->vertexArray());
  // The geometry pass culls back faces (beginGeometryPass); a double-sided object draws both, and
  // its shaders negate the normal of back faces (common/surface.glsl, geometricNormal).
  if (draw.object->doubleSided) g.Disable(GL_CULL_FACE);
  g.DrawElements(GL_TRIANGLES, draw.mesh->indexCount(), GL_UNSIGNED_INT, nullptr);
  if (draw.object->doubleSided) g.Enable(GL_CULL_FACE);
}

Result<SurfacePrograms> buildSurfacePrograms(const gl::GlApi& gl, const gl::ShaderLibrary& library,
                                             const char* fragment) {
  const gl::ShaderDefine defines[] = {{"TISSUE_NORMAL_MAP", "1"}};
  SurfacePrograms out;
  for (const bool mapped : {false, true}) {
    auto program = gl::buildProgram(
        gl, library,
        {"common/surface.vert", fragment, mapped ? std::span(defines) : std::span<const gl::ShaderDefine>()});
    if (!program) return program.error();
    const GLuint id = program->id();
    gl.UseProgram(id);
    gl.Uniform1i(gl.GetUniformLocation(id, "u_baseColor"), kUnitBaseColor);
    gl.Uniform1i(gl.GetUniformLocation(id, "u_normalMap"), kUnitNormalMap);
    (mapped ? out.mapped : out.flat) = std::move(*program);
  }
  return out;
}

void drawFullScreen(const FrameContext& frame) {
  frame.gl.BindVertexArray(frame.emptyVertexArray);
  frame.gl.DrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace tissue::render
