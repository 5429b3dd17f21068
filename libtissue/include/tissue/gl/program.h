#pragma once
/// \file
/// Compiling and linking shader programs from the shader library. Compile and link failures
/// come back as an Error holding the file name and the driver's info log, never an abort.

#include <span>
#include <string>

#include "tissue/core/result.h"
#include "tissue/gl/gl_api.h"
#include "tissue/gl/objects.h"
#include "tissue/gl/shader_library.h"

namespace tissue::gl {

/// Which files make a program, and the variant defines for both stages.
struct ProgramDesc {
  std::string vertex;    ///< e.g. "lit.vert"
  std::string fragment;  ///< e.g. "lit.frag"
  std::span<const ShaderDefine> defines;
};

/// Compiles one stage (`stage` = GL_VERTEX_SHADER or GL_FRAGMENT_SHADER) from preprocessed text;
/// `name` labels errors. Returns the shader name (caller deletes it).
Result<GLuint> compileShader(const GlApi& gl, GLenum stage, const PreprocessedShader& shader,
                             const std::string& name);

/// Builds a program from the library; the context must be current.
Result<Program> buildProgram(const GlApi& gl, const ShaderLibrary& library, const ProgramDesc& desc);

}  // namespace tissue::gl
