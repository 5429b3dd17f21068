#include "gl_environment.h"

#include <cstdlib>
#include <string>

namespace tissue::sim_app {
namespace {

std::string environment(const char* name) {
  const char* value = std::getenv(name);
  return value ? value : "";
}

}  // namespace

Result<std::unique_ptr<context::GlContext>> createAppContext(context::ContextRequest request, bool log) {
  if (request.eglPlatform.empty()) request.eglPlatform = eglPlatformFromEnvironment();
  return context::createHeadlessContext(request, {.backend = glContextFromEnvironment(), .log = log});
}

Result<render::Renderer> createAppRenderer(const context::GlContext& context, int samples, bool gpuTimers) {
  return render::Renderer::create(
      context.procAddressFunction(),
      {.shaders = shaderSettingsFromEnvironment(), .samples = samples, .gpuTimers = gpuTimers});
}

std::string glContextFromEnvironment() {
  return environment("TISSUE_GL_CONTEXT");
}

std::string eglPlatformFromEnvironment() {
  return environment("TISSUE_EGL_PLATFORM");
}

gl::ShaderLibrarySettings shaderSettingsFromEnvironment() {
  return {.overrideDir = environment("TISSUE_SHADER_DIR")};
}

}  // namespace tissue::sim_app
