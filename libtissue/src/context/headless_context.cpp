// Picking a headless context backend from the options, or EGL with OSMesa fallback.
#include "tissue/context/headless_context.h"

#include <iostream>

#include "tissue/context/egl_context.h"
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
  const std::string& backend = options.backend;
  Result<std::unique_ptr<GlContext>> context = Error{};
  if (backend == "egl") {
    context = createEglContext(request);
  } else if (backend == "osmesa") {
    context = createOsMesaContext(request);
  } else if (backend.empty()) {
    context = createEglContext(request);
    if (!context) {
      if (options.log)
        std::cerr << "tissue: EGL failed, falling back to OSMesa: " << context.error().message << std::endl;
      context = createOsMesaContext(request);
    }
  } else {
    return Error{
        "unknown headless GL context backend '" + backend +
        "' (TISSUE_GL_CONTEXT); use egl or osmesa (a window: the viewer, or the host's own context)"};
  }
  if (context && options.log) logInfo((*context)->info());
  return context;
}

}  // namespace tissue::context
