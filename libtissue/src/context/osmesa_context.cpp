// OSMesa core-profile contexts; the default buffer only satisfies OSMesaMakeCurrent.
#include "tissue/context/osmesa_context.h"

#include <GL/osmesa.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace tissue::context {
namespace {

class OsMesaContext final : public GlContext {
 public:
  OsMesaContext(OSMesaContext context, int width, int height)
      : m_context(context),
        m_width(width),
        m_height(height),
        m_buffer(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4) {}
  ~OsMesaContext() override { OSMesaDestroyContext(m_context); }

  Result<void> makeCurrent() override {
    if (!OSMesaMakeCurrent(m_context, m_buffer.data(), GL_UNSIGNED_BYTE, m_width, m_height)) {
      return Error{"osmesa: OSMesaMakeCurrent failed"};
    }
    return {};
  }
  // OSMesa's own entry points, not the glvnd dispatch symbols of the same names.
  gl::GlProc getProcAddress(const char* name) const override { return OSMesaGetProcAddress(name); }
  const ContextInfo& info() const override { return m_info; }
  void setInfo(ContextInfo info) { m_info = std::move(info); }

 private:
  OSMesaContext m_context;
  int m_width;
  int m_height;
  std::vector<std::uint8_t> m_buffer;  // RGBA8, width * height
  ContextInfo m_info;
};

}  // namespace

Result<std::unique_ptr<GlContext>> createOsMesaContext(const ContextRequest& request) {
  const int attribs[] = {OSMESA_FORMAT,
                         OSMESA_RGBA,
                         OSMESA_DEPTH_BITS,
                         24,
                         OSMESA_STENCIL_BITS,
                         8,
                         OSMESA_PROFILE,
                         OSMESA_CORE_PROFILE,
                         OSMESA_CONTEXT_MAJOR_VERSION,
                         request.glMajor,
                         OSMESA_CONTEXT_MINOR_VERSION,
                         request.glMinor,
                         0};
  OSMesaContext raw = OSMesaCreateContextAttribs(attribs, nullptr);
  if (!raw) {
    return Error{"osmesa: OSMesaCreateContextAttribs failed for a GL " + std::to_string(request.glMajor) +
                 "." + std::to_string(request.glMinor) + " core profile"};
  }
  auto context =
      std::make_unique<OsMesaContext>(raw, std::max(request.width, 1), std::max(request.height, 1));
  if (auto current = context->makeCurrent(); !current) return current.error();
  auto info = queryContextInfo(context->procAddressFunction(), request, "osmesa", "osmesa");
  if (!info) return info.error();
  context->setInfo(std::move(*info));
  return std::unique_ptr<GlContext>(std::move(context));
}

}  // namespace tissue::context
