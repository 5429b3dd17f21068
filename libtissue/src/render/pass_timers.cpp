#include "pass_timers.h"

namespace tissue::render {

void PassTimers::beginFrame(const gl::GlApi& gl, bool gpu, bool finish) {
  m_gl = &gl;
  m_gpu = gpu;
  m_finish = finish;
  m_passes.clear();
}

void PassTimers::begin(const std::string& name, int object) {
  if (m_finish) m_gl->Finish();  // earlier passes complete before this one's clock starts
  Running pass;
  pass.timing.name = name;
  pass.timing.object = object;
  if (m_gpu) {
    const std::size_t index = m_passes.size();
    if (m_queries.size() <= index) m_queries.push_back(gl::Query::create(*m_gl));
    pass.query = static_cast<int>(index);
    m_gl->BeginQuery(GL_TIME_ELAPSED, m_queries[index].id());
  }
  m_passes.push_back(std::move(pass));
}

void PassTimers::end() {
  Running& pass = m_passes.back();
  if (pass.query >= 0) m_gl->EndQuery(GL_TIME_ELAPSED);
  if (m_finish) m_gl->Finish();  // llvmpipe rasterises lazily: wait for this pass's fragments
  pass.timing.cpuMs = pass.started.elapsedMs();
}

void PassTimers::issued(int object) {
  if (m_passes.empty()) return;
  Running& pass = m_passes.back();
  const double now = pass.started.elapsedMs();
  pass.timing.issued.push_back({object, now - pass.markedMs});
  pass.markedMs = now;
}

std::vector<PassTiming> PassTimers::finishFrame() {
  std::vector<PassTiming> out;
  out.reserve(m_passes.size());
  for (Running& pass : m_passes) {
    if (pass.query >= 0) {
      GLuint64 ns = 0;
      m_gl->GetQueryObjectui64v(m_queries[static_cast<std::size_t>(pass.query)].id(), GL_QUERY_RESULT, &ns);
      const double ms = static_cast<double>(ns) * 1e-6;
      // A result longer than the wall clock since the pass began is impossible: llvmpipe
      // (Mesa 22.3) returns the time since boot for the first query on a new framebuffer.
      pass.timing.gpuMs = ms <= pass.started.elapsedMs() ? ms : -1.0;
    }
    out.push_back(pass.timing);
  }
  return out;
}

}  // namespace tissue::render
