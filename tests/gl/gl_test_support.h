#pragma once
// Creating a context of one backend in a GL test, or failing the test with the reason.
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

/// Declares `var` as a current context of `backend`, or fails the test saying why: a broken
/// context set-up must fail CI, never pass it by skipping.
#define TISSUE_CONTEXT_OR_FAIL(var, backend)                                 \
  auto var##Result = ::tissue::test::createContext(backend);                 \
  if (!var##Result)                                                          \
    GTEST_FAIL() << ::tissue::test::backendName(backend)                     \
                 << " context unavailable: " << var##Result.error().message; \
  auto& var = *var##Result
