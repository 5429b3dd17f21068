#pragma once
/// \file
/// Move-only RAII GL object names. An object created here owns its name and deletes it on
/// destruction (the context that created it, or one sharing with it, must then be current);
/// `wrap()` adopts a host's name without owning it: the wrapper never deletes it.

#include <cstdint>
#include <memory>
#include <utility>

#include "tissue/gl/gl_api.h"

namespace tissue::gl {

/// The kinds of GL object names this library manages.
enum class ObjectKind { Buffer, VertexArray, Texture, Framebuffer, Renderbuffer, Query, Program };

/// One GL object name of kind `K`: owned (deleted on destruction) or wrapped (a host's).
template <ObjectKind K>
class Object {
 public:
  Object() = default;
  ~Object() { reset(); }
  Object(const Object&) = delete;
  Object& operator=(const Object&) = delete;
  Object(Object&& other) noexcept { *this = std::move(other); }
  Object& operator=(Object&& other) noexcept {
    if (this != &other) {
      reset();
      m_gl = std::exchange(other.m_gl, nullptr);
      m_id = std::exchange(other.m_id, 0u);
      m_owned = std::exchange(other.m_owned, false);
    }
    return *this;
  }

  /// Generates a new name in the current context (for Program: glCreateProgram).
  static Object create(const GlApi& gl);
  /// Adopts `id` from a host without taking ownership; destruction leaves it alive.
  static Object wrap(const GlApi& gl, GLuint id) { return Object(gl, id, false); }

  /// The GL name (0 when empty).
  GLuint id() const { return m_id; }
  /// Whether this wrapper deletes the name on destruction.
  bool owned() const { return m_owned; }
  explicit operator bool() const { return m_id != 0; }
  /// Gives up ownership and returns the name; the wrapper becomes empty.
  GLuint release() {
    m_gl = nullptr;
    m_owned = false;
    return std::exchange(m_id, 0u);
  }
  /// Deletes the name when owned; the wrapper becomes empty.
  void reset();

 private:
  Object(const GlApi& gl, GLuint id, bool owned) : m_gl(&gl), m_id(id), m_owned(owned) {}
  const GlApi* m_gl = nullptr;
  GLuint m_id = 0;
  bool m_owned = false;
};

using Buffer = Object<ObjectKind::Buffer>;              ///< glGenBuffers
using VertexArray = Object<ObjectKind::VertexArray>;    ///< glGenVertexArrays
using Texture = Object<ObjectKind::Texture>;            ///< glGenTextures
using Framebuffer = Object<ObjectKind::Framebuffer>;    ///< glGenFramebuffers
using Renderbuffer = Object<ObjectKind::Renderbuffer>;  ///< glGenRenderbuffers
using Query = Object<ObjectKind::Query>;                ///< glGenQueries
using Program = Object<ObjectKind::Program>;            ///< glCreateProgram

/// The GL object names alive in the current context's share group, counted by asking GL itself
/// (glIsBuffer, glIsTexture, ...) for every name 1..maxName: a leak check that does not trust
/// this library's own bookkeeping (a soak run's GL objects must stay constant after warm-up).
/// A name generated but never bound is not yet an object (GL 3.3 core §2.5) and is not counted.
/// Slow (a few hundred thousand queries): for tests and soak runs, never on the frame path.
struct ObjectCensus {
  int buffers = 0;
  int vertexArrays = 0;  ///< of the current context (vertex arrays are not shared)
  int textures = 0;
  int framebuffers = 0;  ///< of the current context (not shared)
  int renderbuffers = 0;
  int queries = 0;
  int programs = 0;
  int shaders = 0;
  int total() const {
    return buffers + vertexArrays + textures + framebuffers + renderbuffers + queries + programs + shaders;
  }
  bool operator==(const ObjectCensus&) const = default;
};
ObjectCensus countLiveObjects(const GlApi& gl, GLuint maxName = 8192);

extern template class Object<ObjectKind::Buffer>;
extern template class Object<ObjectKind::VertexArray>;
extern template class Object<ObjectKind::Texture>;
extern template class Object<ObjectKind::Framebuffer>;
extern template class Object<ObjectKind::Renderbuffer>;
extern template class Object<ObjectKind::Query>;
extern template class Object<ObjectKind::Program>;

}  // namespace tissue::gl
