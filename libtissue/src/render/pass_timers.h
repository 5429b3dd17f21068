#pragma once
// Named passes of one frame, each timed on the CPU and with a GL_TIME_ELAPSED query. The
// queries are collected once at the end of the frame (one wait, not one per pass).
#include <string>
#include <vector>

#include "tissue/core/result.h"
#include "tissue/core/stopwatch.h"
#include "tissue/gl/objects.h"
#include "tissue/render/renderer.h"

namespace tissue::render {

class PassTimers {
 public:
  /// Starts a frame; `gpu` turns the timer queries on, `finish` waits for the GPU around every
  /// pass (RendererSettings::finishPasses).
  void beginFrame(const gl::GlApi& gl, bool gpu, bool finish = false);
  /// Runs `pass` (a callable returning Result<void>) as the pass `name`, the work of scene
  /// object `object` (PassTiming::object; -1: of the frame or of a method as a whole).
  template <class F>
  Result<void> run(const std::string& name, F&& pass, int object = -1) {
    begin(name, object);
    Result<void> r = pass();
    end();
    return r;
  }
  /// Within a running pass that draws several objects: the CPU ms since the pass began (or since
  /// the last call) were spent issuing `object`'s draw (PassTiming::issued). No finish.
  void issued(int object);
  /// Waits for the queries and returns every pass of the frame, in order.
  std::vector<PassTiming> finishFrame();

 private:
  struct Running {
    PassTiming timing;
    Stopwatch started;      // wall clock since the pass began: bounds a plausible GPU time
    double markedMs = 0.0;  // ms since the start at the last `issued`
    int query = -1;
  };
  void begin(const std::string& name, int object);
  void end();
  const gl::GlApi* m_gl = nullptr;
  bool m_gpu = false;
  bool m_finish = false;
  std::vector<gl::Query> m_queries;  // grows to the most passes a frame has had
  std::vector<Running> m_passes;
};

}  // namespace tissue::render
