#pragma once
// Creating a context of one backend in a GL test, or skipping the test with the reason.
#include <gtest/gtest.h>

#include "tissue/context/egl_context.h"
#include "tissue/context/osmesa_context.h"

namespace tissue::test {

enum class Backend { Egl, OsMesa };

inline const char* backendName(Backend b) {
  return b == Backend::Egl ? "egl" : "osmesa";
}

/// Names parameterised tests after the backend (gtest's name generator).
inline std::string backendParamName(const ::testing::TestParamInfo<Backend>& info) {
  return backendName(info.param);
}

inline Result<std::unique_ptr<context::GlContext>> createContext(Backend b) {
  return b == Backend::Egl ? context::createEglContext() : context::createOsMesaContext();
}

}  // namespace tissue::test

/// Declares `var` as a current context of `backend`, or skips the test saying why.
#define TISSUE_CONTEXT_OR_SKIP(var, backend)                                 \
  auto var##Result = ::tissue::test::createContext(backend);                 \
  if (!var##Result)                                                          \
    GTEST_SKIP() << ::tissue::test::backendName(backend)                     \
                 << " context unavailable: " << var##Result.error().message; \
  auto& var = *var##Result
