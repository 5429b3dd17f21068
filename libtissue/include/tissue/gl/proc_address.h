#pragma once
/// \file
/// How GL entry points are found: a function from name to address, given by whoever owns the
/// context (a tissue context backend, or a host application with its own). Light header: no GL.

#include <functional>

namespace tissue::gl {

/// An untyped GL function pointer, as eglGetProcAddress / glfwGetProcAddress return it.
using GlProc = void (*)();

/// Looks up a GL entry point of the context current when it is called; null when unknown.
using GetProcAddressFn = std::function<GlProc(const char* name)>;

}  // namespace tissue::gl
