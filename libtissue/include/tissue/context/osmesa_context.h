#pragma once
/// \file
/// Off-screen Mesa contexts (target tissue_context_osmesa): OSMesaCreateContextAttribs with a
/// core profile. Its own colour buffer only satisfies OSMesaMakeCurrent; tissue renders into
/// framebuffer objects. GL entry points come from OSMesaGetProcAddress, so they are OSMesa's
/// even when libOpenGL (glvnd) is loaded in the same process.

#include <memory>

#include "tissue/context/gl_context.h"

namespace tissue::context {

/// Creates an OSMesa core context of at least `request`'s version and makes it current.
Result<std::unique_ptr<GlContext>> createOsMesaContext(const ContextRequest& request = {});

}  // namespace tissue::context
