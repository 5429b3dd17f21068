// Compiling and linking programs; the info log comes back in the Error.
#include "tissue/gl/program.h"

#include <string>
#include <vector>

namespace tissue::gl {
namespace {

std::string fileTable(const PreprocessedShader& shader) {
  std::string s;
  for (std::size_t i = 0; i < shader.files.size(); ++i) {
    s += (i ? ", " : "") + std::to_string(i) + "=" + shader.files[i];
  }
  return s;
}

std::string trimmedLog(std::string log) {
  while (!log.empty() && (log.back() == '\n' || log.back() == '\0' || log.back() == ' '))
    log.pop_back();
  return log;
}

}  // namespace

Result<GLuint> compileShader(const GlApi& gl, GLenum stage, const PreprocessedShader& shader,
                             const std::string& name) {
  const GLuint id = gl.CreateShader(stage);
  if (id == 0) return Error{"shader " + name + ": glCreateShader failed (is a context current?)"};
  const char* text = shader.source.c_str();
  gl.ShaderSource(id, 1, &text, nullptr);
  gl.CompileShader(id);
  GLint ok = GL_FALSE;
  gl.GetShaderiv(id, GL_COMPILE_STATUS, &ok);
  if (ok == GL_TRUE) return id;
  GLint length = 0;
  gl.GetShaderiv(id, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(length > 0 ? length : 0), '\0');
  if (length > 0) gl.GetShaderInfoLog(id, length, nullptr, log.data());
  gl.DeleteShader(id);
  // Log locations read "string:line"; the table maps string numbers to files.
  return Error{"shader " + name + " failed to compile (source strings: " + fileTable(shader) +
               "): " + trimmedLog(std::move(log))};
}

Result<Program> buildProgram(const GlApi& gl, const ShaderLibrary& library, const ProgramDesc& desc) {
  // Step 1: preprocess and compile both stages.
  auto vs = library.preprocess(desc.vertex, desc.defines);
  if (!vs) return vs.error();
  auto fs = library.preprocess(desc.fragment, desc.defines);
  if (!fs) return fs.error();
  auto vertex = compileShader(gl, GL_VERTEX_SHADER, *vs, desc.vertex);
  if (!vertex) return vertex.error();
  auto fragment = compileShader(gl, GL_FRAGMENT_SHADER, *fs, desc.fragment);
  if (!fragment) {
    gl.DeleteShader(*vertex);
    return fragment.error();
  }
  // Step 2: link; the shaders are flagged for deletion once attached.
  Program program = Program::create(gl);
  gl.AttachShader(program.id(), *vertex);
  gl.AttachShader(program.id(), *fragment);
  gl.LinkProgram(program.id());
  gl.DetachShader(program.id(), *vertex);
  gl.DetachShader(program.id(), *fragment);
  gl.DeleteShader(*vertex);
  gl.DeleteShader(*fragment);
  GLint ok = GL_FALSE;
  gl.GetProgramiv(program.id(), GL_LINK_STATUS, &ok);
  if (ok == GL_TRUE) return program;
  GLint length = 0;
  gl.GetProgramiv(program.id(), GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(length > 0 ? length : 0), '\0');
  if (length > 0) gl.GetProgramInfoLog(program.id(), length, nullptr, log.data());
  return Error{"program " + desc.vertex + " + " + desc.fragment +
               " failed to link: " + trimmedLog(std::move(log))};
}

}  // namespace tissue::gl
