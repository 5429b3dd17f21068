#include "embedding_scene.h"

#include <cmath>
#include <cstring>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace tissue::test {
namespace {

GLuint compile(const gl::GlApi& g, GLenum type, const char* source) {
  const GLuint s = g.CreateShader(type);
  g.ShaderSource(s, 1, &source, nullptr);
  g.CompileShader(s);
  GLint ok = 0;
  g.GetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    g.DeleteShader(s);
    return 0;
  }
  return s;
}

std::vector<Float4> gaussian(float sigmaMm, int taps) {
  std::vector<Float4> k;
  float sum = 0.0f;
  for (int i = 0; i < taps; ++i) {
    const float x = (-3.0f + 6.0f * float(i) / float(taps - 1)) * sigmaMm;
    const float w = std::exp(-x * x / (2.0f * sigmaMm * sigmaMm));
    k.push_back({w, w, w, x});
    sum += w;
  }
  for (Float4& t : k)
    t = {t.x / sum, t.y / sum, t.z / sum, t.w};
  return k;
}

}  // namespace

PlanarSphere makePlanarSphere(float radiusMm, int rings, int segments) {
  PlanarSphere s{makeSphere(radiusMm, rings, segments), {}};
  for (std::size_t i = 0; i < s.mesh.positions.size(); ++i) {
    const Float3 n = s.mesh.normals[i];
    const Float4 t = s.mesh.tangents[i];
    glm::vec3 ns = glm::vec3(n.x, n.y, n.z) + 0.25f * glm::vec3(t.x, t.y, t.z);
    ns = glm::normalize(ns);
    s.planes.push_back({ns.x, ns.y, ns.z, 0.3f});
  }
  return s;
}

Result<MethodTextures> uploadMethodTextures(render::Renderer& renderer) {
  MethodTextures t;
  auto base = renderer.createTexture(makeBaseColor(128));
  auto normal = renderer.createTexture(makeBumpyNormalMap(128));
  Image8 map(8, 8, 4);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x)
      for (int c = 0; c < 4; ++c)
        map.at(x, y)[c] = std::uint8_t(40 * (c + 1) + 4 * ((x + y) % 3));  // increasing boundaries
  auto subsurface = renderer.createTexture(map, render::TextureEncoding::LinearData);
  if (!base) return base.error();
  if (!normal) return normal.error();
  if (!subsurface) return subsurface.error();
  t.baseColor = *base, t.normalMap = *normal, t.subsurface = *subsurface;
  return t;
}

render::MethodSettings methodSettings(render::ShadingMethod method, const MethodTextures& textures,
                                      float uvPerMm) {
  switch (method) {
    case render::ShadingMethod::Lit:
      return render::LitSettings{};
    case render::ShadingMethod::Separable: {
      render::SeparableSettings s = render::rankOneSeparable(gaussian(1.2f, 9));
      s.transmittance = {{0.6f, 0.3f, 0.2f, 1.0f}, {0.2f, 0.05f, 0.02f, 6.0f}};
      return s;
    }
    case render::ShadingMethod::TextureSpace:
      return skinTextureSpace(256, true);
    case render::ShadingMethod::RayMarch: {
      render::RayMarchSettings s;
      s.layers = {{{2.0f, 1.0f, 1.0f}, {2.6f, 1.6f, 1.6f}, 0.25f},
                  {{3.7f, 4.4f, 5.05f}, {3.732f, 4.57f, 5.53f}, 0.0f},
                  {{6.0f, 3.0f, 2.0f}, {6.6f, 3.6f, 2.6f}, 0.4f},
                  {{0.5f, 0.5f, 0.5f}, {1.0f, 1.2f, 1.4f}, -0.3f},
                  {{1.0f, 1.0f, 2.0f}, {1.5f, 1.5f, 2.5f}, 0.8f}};
      s.subsurfaceMaps = {textures.subsurface};
      s.depthScaleMm = 2.0f;
      s.uvPerMm = uvPerMm;
      s.samples = 24;
      s.jitter = false;
      return s;
    }
    case render::ShadingMethod::Parallax: {
      render::ParallaxSettings s;
      s.layers = {render::ParallaxLayer{textures.baseColor, 1.5f, 1.0f}};
      s.lightmap.size = 256;
      s.lightmap.reduction = 4;
      return s;
    }
  }
  return render::LitSettings{};
}

render::SceneObject methodObject(render::ShadingMethod method, render::MeshHandle mesh,
                                 const MethodTextures& textures, float uvPerMm) {
  render::SceneObject o;
  o.mesh = mesh;
  o.baseColor = textures.baseColor;
  o.normalMap = textures.normalMap;
  o.material.specular = 0.1f;
  o.method = methodSettings(method, textures, uvPerMm);
  return o;
}

HostDrawer::HostDrawer(const gl::GlApi& gl) : m_gl(gl) {
  const char* vs =
      "#version 330 core\n"
      "layout(location = 0) in vec3 a_position;\n"
      "uniform mat4 u_viewProjection;\n"
      "void main() { gl_Position = u_viewProjection * vec4(a_position, 1.0); }\n";
  const char* fs =
      "#version 330 core\n"
      "uniform vec4 u_color;\n"
      "out vec4 o_color;\n"
      "void main() { o_color = u_color; }\n";
  const GLuint v = compile(gl, GL_VERTEX_SHADER, vs), f = compile(gl, GL_FRAGMENT_SHADER, fs);
  if (!v || !f) return;
  const GLuint p = gl.CreateProgram();
  gl.AttachShader(p, v);
  gl.AttachShader(p, f);
  gl.LinkProgram(p);
  gl.DeleteShader(v);
  gl.DeleteShader(f);
  GLint linked = 0;
  gl.GetProgramiv(p, GL_LINK_STATUS, &linked);
  if (!linked) {
    gl.DeleteProgram(p);
    return;
  }
  m_program = p;
  gl.GenVertexArrays(1, &m_vertexArray);
  gl.GenBuffers(1, &m_buffer);
  gl.BindVertexArray(m_vertexArray);
  gl.BindBuffer(GL_ARRAY_BUFFER, m_buffer);
  gl.BufferData(GL_ARRAY_BUFFER, 4 * sizeof(Float3), nullptr, GL_DYNAMIC_DRAW);
  gl.EnableVertexAttribArray(0);
  gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Float3), nullptr);
  gl.BindVertexArray(0);
}

HostDrawer::~HostDrawer() {
  if (m_program) m_gl.DeleteProgram(m_program);
  if (m_buffer) m_gl.DeleteBuffers(1, &m_buffer);
  if (m_vertexArray) m_gl.DeleteVertexArrays(1, &m_vertexArray);
}

void HostDrawer::quad(const Mat4& viewProjection, const std::array<Float3, 4>& corners,
                      const Float4& rgba) const {
  const gl::GlApi& g = m_gl;
  g.UseProgram(m_program);
  g.UniformMatrix4fv(g.GetUniformLocation(m_program, "u_viewProjection"), 1, GL_FALSE, viewProjection.data());
  g.Uniform4f(g.GetUniformLocation(m_program, "u_color"), rgba.x, rgba.y, rgba.z, rgba.w);
  g.BindVertexArray(m_vertexArray);
  g.BindBuffer(GL_ARRAY_BUFFER, m_buffer);
  // a, b, d, c as a strip.
  const Float3 strip[4] = {corners[0], corners[1], corners[3], corners[2]};
  g.BufferSubData(GL_ARRAY_BUFFER, 0, sizeof(strip), strip);
  g.DrawArrays(GL_TRIANGLE_STRIP, 0, 4);
}

Mat4 hostViewProjection(const render::Camera& c, float aspect) {
  const glm::mat4 view =
      glm::lookAt(glm::vec3(c.eye.x, c.eye.y, c.eye.z), glm::vec3(c.target.x, c.target.y, c.target.z),
                  glm::vec3(c.up.x, c.up.y, c.up.z));
  const glm::mat4 projection = glm::perspective(glm::radians(c.verticalFovDeg), aspect, c.nearMm, c.farMm);
  const glm::mat4 m = projection * view;
  Mat4 out;
  std::memcpy(out.data(), glm::value_ptr(m), sizeof(float) * 16);
  return out;
}

std::string methodTestName(render::ShadingMethod method) {
  std::string name(render::shadingMethodName(method));
  for (char& c : name)
    if (c == '-') c = '_';
  return name;
}

}  // namespace tissue::test
