#include "lit.h"

#include <variant>

namespace tissue::render {

Result<LitMethod> LitMethod::create(const gl::GlApi& gl, const gl::ShaderLibrary& library) {
  auto programs = buildSurfacePrograms(gl, library, "lit/lit.frag");
  if (!programs) return programs.error();
  LitMethod m;
  m.m_programs = std::move(*programs);
  return m;
}

Result<void> LitMethod::draw(const FrameContext& frame, std::span<const ObjectDraw> objects) const {
  return frame.passes.run("lit", [&]() -> Result<void> {
    beginGeometryPass(frame);
    for (const GLuint program : {m_programs.flat.id(), m_programs.mapped.id()}) {
      bool framed = false;
      for (const ObjectDraw& d : objects) {
        if (m_programs.pick(d) != program) continue;
        if (!framed) setFrameUniforms(frame, program);
        framed = true;
        const auto* lit = std::get_if<LitSettings>(&d.object->method);
        frame.gl.Uniform1f(frame.gl.GetUniformLocation(program, "u_wrap"), lit ? lit->wrap : 0.0f);
        drawSurface(frame, program, d);
        frame.passes.issued(d.index());  // PassTiming::issued
      }
    }
    return gl::checkGlError(frame.gl, "renderer: lit pass");
  });
}

}  // namespace tissue::render
