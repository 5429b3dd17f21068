// Picking a context backend from the request, the environment, or EGL with OSMesa fallback.
#include "tissue/context/headless_context.h"

#include <cstdlib>
#include <iostream>

#include "tissue/context/egl_context.h"
#include "tissue/context/glfw_context.h"
#include "tissue/context/osmesa_context.h"

namespace tissue::context {
namespace {

void logInfo(const ContextInfo& info) {
  std::cerr << "tissue: GL context " << info.backend << " (" << info.platform << "): " << info.vendor << " | "
            << info.renderer << " | " << info.version << std::endl;
}

}  // namespace

Result<std::unique_ptr<GlContext>> createHeadlessContext(const ContextRequest& request,
                                                         const HeadlessOptions& options) {
  std::string backend = options.backend;
  if (backend.empty()) {
    if (const char* env = std::getenv("TISSUE_GL_CONTEXT"); env && *env) backend = env;
  }
  Result<std::unique_ptr<GlContext>> context = Error{};
  if (backend == "egl") {
    context = createEglContext(request);
  } else if (backend == "osmesa") {
    context = createOsMesaContext(request);
  } else if (backend == "glfw") {
    context = createGlfwContext(request);
  } else if (backend.empty()) {
    context = createEglContext(request);
    if (!context) {
      if (options.log)
        std::cerr << "tissue: EGL failed, falling back to OSMesa: " << context.error().message << std::endl;
      context = createOsMesaContext(request);
    }
  } else {
    return Error{"unknown GL context backend '" + backend + "' (TISSUE_GL_CONTEXT); use egl, osmesa or glfw"};
  }
  if (context && options.log) logInfo((*context)->info());
  return context;
}

}  // namespace tissue::context
