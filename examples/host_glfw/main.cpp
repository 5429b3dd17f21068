// An example host of tissue: a GLFW application that owns its window and GL context, draws its
// own instrument and floor with raw GL 3.3 core, and embeds tissue through the installed package
// (CMake: find_package(tissue), target tissue::tissue, header <tissue/tissue.h>).
//
// Each frame, as a simulator would:
//   1 the host moves its instrument (a sphere tip on a shaft) down into the liver and tells
//     tissue the pose                                   scene.setInstrumentPose
//   2 tissue simulates and updates the mesh (no GL)     scene.step(dt)
//   3 the host clears and draws its instrument          raw GL, depth on
//   4 tissue renders into the host's framebuffer, tested against the host's depth and writing
//     its own                                           scene.render(HostFramebuffer)
//   5 the host draws its floor under everything         raw GL, GL_LESS: hidden behind tissue
//
//   host_glfw DATA_DIR [--frames N] [--check OUT.png]
// --check reads the last frame back, writes it as PNG and verifies pixel by pixel that the
// instrument hides the tissue behind it and the tissue hides the floor; exit 0 when it does.
// Needs a display (xvfb-run -a host_glfw ... when headless).
#define GL_GLEXT_PROTOTYPES
#include <GL/glcorearb.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include <tissue/tissue.h>

namespace {

constexpr int kWidth = 480, kHeight = 360;
constexpr float kToolRadiusMm = 8.0f;             // the scenario's sphere
constexpr float kFloorZMm = -40.0f;               // below the liver (z >= -31 mm)
const float kToolColour[3] = {0.0f, 1.0f, 0.0f};  // flat, unlit: exact pixels for the check
const float kFloorColour[3] = {0.0f, 0.0f, 1.0f};

// --- the host's own raw GL: one flat-colour program, triangle lists -----------------------

const char* kVertex = R"(#version 330 core
layout(location = 0) in vec3 a_position;
uniform mat4 u_viewProjection;
void main() { gl_Position = u_viewProjection * vec4(a_position, 1.0); })";
const char* kFragment = R"(#version 330 core
uniform vec3 u_colour;
out vec4 o_colour;
void main() { o_colour = vec4(u_colour, 1.0); })";

GLuint compile(GLenum type, const char* source) {
  GLuint s = glCreateShader(type);
  glShaderSource(s, 1, &source, nullptr);
  glCompileShader(s);
  return s;
}

struct FlatMesh {
  GLuint vao = 0, vbo = 0;
  GLsizei count = 0;
  void upload(const std::vector<float>& xyz) {
    if (!vao) glGenVertexArrays(1, &vao), glGenBuffers(1, &vbo);
    glBindVertexArray(vao);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(xyz.size() * sizeof(float)), xyz.data(), GL_DYNAMIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    count = GLsizei(xyz.size() / 3);
  }
};

/// A sphere of radius r at c and a shaft (a square prism 2 mm wide) from its top up to c + 80 mm.
std::vector<float> instrumentTriangles(tissue::Float3 c, float r) {
  std::vector<float> v;
  auto put = [&](tissue::Float3 p) { v.insert(v.end(), {p.x, p.y, p.z}); };
  const int rings = 16, segments = 24;
  auto at = [&](int i, int j) {
    const float theta = float(M_PI) * float(i) / rings, phi = 2.0f * float(M_PI) * float(j) / segments;
    return tissue::Float3{c.x + r * std::sin(theta) * std::cos(phi),
                          c.y + r * std::sin(theta) * std::sin(phi), c.z + r * std::cos(theta)};
  };
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      put(at(i, j)), put(at(i + 1, j)), put(at(i + 1, j + 1));
      put(at(i, j)), put(at(i + 1, j + 1)), put(at(i, j + 1));
    }
  const float w = 1.0f, z0 = c.z, z1 = c.z + 80.0f;
  const tissue::Float3 corner[4] = {
      {c.x - w, c.y - w, 0}, {c.x + w, c.y - w, 0}, {c.x + w, c.y + w, 0}, {c.x - w, c.y + w, 0}};
  for (int k = 0; k < 4; ++k) {
    const tissue::Float3 a = corner[k], b = corner[(k + 1) % 4];
    put({a.x, a.y, z0}), put({b.x, b.y, z0}), put({b.x, b.y, z1});
    put({a.x, a.y, z0}), put({b.x, b.y, z1}), put({a.x, a.y, z1});
  }
  return v;
}

// --- the host's camera, shared with tissue (the same view and projection) ----------------

struct HostCamera {
  tissue::render::Camera camera;
  float viewProjection[16];
};

HostCamera makeCamera() {
  HostCamera h;
  auto& c = h.camera;
  c.eye = {30.0f, -220.0f, 200.0f};  // in front of and above the liver, looking down at it
  c.target = {0.0f, 0.0f, 5.0f};
  c.up = {0.0f, 0.0f, 1.0f};
  c.verticalFovDeg = 40.0f;
  c.nearMm = 10.0f;
  c.farMm = 3000.0f;
  // gluLookAt and gluPerspective, column-major, as GL (and tissue) build them.
  using tissue::cross, tissue::dot, tissue::normalize;
  const tissue::Float3 f = normalize(c.target - c.eye), s = normalize(cross(f, c.up)), u = cross(s, f);
  const float view[16] = {
      s.x,           u.x, -f.x, 0, s.y, u.y, -f.y, 0, s.z, u.z, -f.z, 0, -dot(s, c.eye), -dot(u, c.eye),
      dot(f, c.eye), 1};
  const float t = 1.0f / std::tan(c.verticalFovDeg * float(M_PI) / 360.0f), aspect = float(kWidth) / kHeight;
  const float n = c.nearMm, fa = c.farMm;
  const float proj[16] = {
      t / aspect, 0, 0, 0, 0, t, 0, 0, 0, 0, (fa + n) / (n - fa), -1, 0, 0, 2 * fa * n / (n - fa), 0};
  for (int col = 0; col < 4; ++col)
    for (int row = 0; row < 4; ++row) {
      float sum = 0;
      for (int k = 0; k < 4; ++k)
        sum += proj[k * 4 + row] * view[col * 4 + k];
      h.viewProjection[col * 4 + row] = sum;
    }
  return h;
}

/// The pixel (x right, y down) where world point p lands.
bool project(const HostCamera& h, tissue::Float3 p, int& x, int& y) {
  const float* m = h.viewProjection;
  const float cx = m[0] * p.x + m[4] * p.y + m[8] * p.z + m[12],
              cy = m[1] * p.x + m[5] * p.y + m[9] * p.z + m[13],
              cw = m[3] * p.x + m[7] * p.y + m[11] * p.z + m[15];
  if (cw <= 0) return false;
  x = int((cx / cw * 0.5f + 0.5f) * kWidth);
  y = int((0.5f - cy / cw * 0.5f) * kHeight);
  return x >= 0 && x < kWidth && y >= 0 && y < kHeight;
}

// --- the check -------------------------------------------------------------------------

enum class Kind { Tool, Floor, Tissue };
Kind classify(const std::uint8_t* p) {
  if (p[0] < 8 && p[1] > 247 && p[2] < 8) return Kind::Tool;
  if (p[0] < 8 && p[1] < 8 && p[2] > 247) return Kind::Floor;
  return Kind::Tissue;
}

int check(const tissue::Image8& image, const HostCamera& h, tissue::Float3 tip) {
  long counts[3] = {0, 0, 0};
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      ++counts[int(classify(image.at(x, y)))];
  std::printf("host_glfw: pixels: instrument %ld, floor %ld, tissue %ld of %d\n", counts[0], counts[1],
              counts[2], kWidth * kHeight);
  int failures = 0;
  auto expect = [&](bool ok, const std::string& what) {
    std::printf("host_glfw: %s: %s\n", ok ? "ok" : "FAILED", what.c_str());
    failures += !ok;
  };
  // The instrument in front of the tissue: its shaft above the surface and the top of its tip,
  // drawn before tissue, survive tissue's render (tissue tested against the host's depth).
  int inFront = 0, samples = 0;
  for (float dz : {kToolRadiusMm * 0.9f, 12.0f, 20.0f, 30.0f, 40.0f}) {
    int x, y;
    if (!project(h, {tip.x, tip.y, tip.z + dz}, x, y)) continue;
    ++samples;
    inFront += classify(image.at(x, y)) == Kind::Tool;
  }
  expect(samples == 5 && inFront == samples, "the host's instrument hides the tissue behind it (" +
                                                 std::to_string(inFront) + " of 5 points on the tool)");
  // The tissue in front of the floor: the floor, drawn last with GL_LESS, shows only around it.
  expect(counts[2] > long(kWidth) * kHeight / 8, "the tissue hides the floor behind it");
  int x, y;
  expect(project(h, {-30.0f, 0.0f, 20.0f}, x, y) && classify(image.at(x, y)) == Kind::Tissue,
         "the organ's middle shows tissue");
  expect(classify(image.at(2, kHeight - 3)) == Kind::Floor &&
             classify(image.at(kWidth - 3, kHeight - 3)) == Kind::Floor,
         "the floor shows where no tissue is in front");
  expect(counts[0] > 200, "the instrument is drawn");
  return failures;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: host_glfw DATA_DIR [--frames N] [--check OUT.png]\n");
    return 2;
  }
  const std::string data = argv[1];
  int frames = 150;
  std::string checkPng;
  for (int i = 2; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--frames"))
      frames = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--check"))
      checkPng = argv[i + 1];
  }

  // The host's window and context (GL 3.3 core); tissue gets its getProcAddress.
  if (!glfwInit()) return std::fprintf(stderr, "host_glfw: no display for GLFW (use xvfb-run -a)\n"), 1;
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_VISIBLE, checkPng.empty() ? GLFW_TRUE : GLFW_FALSE);
  GLFWwindow* window = glfwCreateWindow(kWidth, kHeight, "tissue host example", nullptr, nullptr);
  if (!window) return std::fprintf(stderr, "host_glfw: no GL 3.3 core window\n"), glfwTerminate(), 1;
  glfwMakeContextCurrent(window);

  int status = 0;
  {
    auto scene = tissue::scene::Scene::create([](const char* name) { return glfwGetProcAddress(name); });
    if (!scene) return std::fprintf(stderr, "host_glfw: %s\n", scene.error().message.c_str()), 1;
    tissue::scene::OrganDesc liver;
    liver.material = data + "/materials/liver.json";
    liver.scenario = data + "/scenarios/liver_poke_grasp.json";
    liver.method = tissue::render::ShadingMethod::Separable;
    auto organ = scene->addOrgan(liver);
    if (!organ) return std::fprintf(stderr, "host_glfw: %s\n", organ.error().message.c_str()), 1;
    scene->setInstrumentVisible(false);  // the host draws its own
    const HostCamera camera = makeCamera();
    scene->setCamera(camera.camera);

    const GLuint program = glCreateProgram();
    glAttachShader(program, compile(GL_VERTEX_SHADER, kVertex));
    glAttachShader(program, compile(GL_FRAGMENT_SHADER, kFragment));
    glLinkProgram(program);
    FlatMesh tool, floor;
    const float F = 1500.0f;
    floor.upload({-F, -F, kFloorZMm, F, -F, kFloorZMm, F, F, kFloorZMm, -F, -F, kFloorZMm, F, F, kFloorZMm,
                  -F, F, kFloorZMm});

    tissue::Float3 tip{31.82f, 0.0f, 75.0f};
    // CPU wall time of tissue's calls per frame, and of the host's whole frame up to the swap (on a
    // lazy rasteriser such as llvmpipe the drawing is paid at the swap).
    std::vector<double> stepMs, renderMs, frameMs, hostMs;
    for (int frame = 0; frame < frames && !glfwWindowShouldClose(window); ++frame) {
      // 1 the host's instrument: held above for 1 s while the liver settles, then 10 mm into it.
      const float down = std::clamp(float(frame - 60) / 80.0f, 0.0f, 1.0f);
      tip.z = 75.0f - 25.7f * down;
      (void)scene->setInstrumentPose({.tipMm = tip, .axis = {0, 0, 1}, .radiusMm = kToolRadiusMm});
      // 2 simulation and mesh update (no GL)
      tissue::Stopwatch watch, whole;
      if (auto s = scene->step(1.0 / 60.0); !s) {
        std::fprintf(stderr, "host_glfw: %s\n", s.error().message.c_str());
        status = 1;
        break;
      }
      stepMs.push_back(watch.elapsedMs());
      // 3 the host's frame: clear, its instrument
      glViewport(0, 0, kWidth, kHeight);
      glClearColor(0.2f, 0.2f, 0.2f, 1.0f);
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
      glEnable(GL_DEPTH_TEST);
      glDepthFunc(GL_LESS);
      glUseProgram(program);
      glUniformMatrix4fv(glGetUniformLocation(program, "u_viewProjection"), 1, GL_FALSE,
                         camera.viewProjection);
      tool.upload(instrumentTriangles(tip, kToolRadiusMm));
      glUniform3fv(glGetUniformLocation(program, "u_colour"), 1, kToolColour);
      glBindVertexArray(tool.vao);
      glDrawArrays(GL_TRIANGLES, 0, tool.count);
      // 4 tissue into the host's framebuffer, with its depth
      tissue::render::HostFramebuffer target;
      target.framebuffer = 0;
      target.width = kWidth;
      target.height = kHeight;
      target.clear = false;
      target.depth = tissue::render::HostDepth::TestAndWrite;
      watch.restart();
      if (auto r = scene->render(target); !r) {
        std::fprintf(stderr, "host_glfw: %s\n", r.error().message.c_str());
        status = 1;
        break;
      }
      renderMs.push_back(watch.elapsedMs());
      frameMs.push_back(stepMs.back() + renderMs.back());
      // 5 the host's floor, after tissue: tissue restored the host's state (program, VAO, depth)
      glUseProgram(program);
      glUniform3fv(glGetUniformLocation(program, "u_colour"), 1, kFloorColour);
      glBindVertexArray(floor.vao);
      glDrawArrays(GL_TRIANGLES, 0, floor.count);
      if (frame + 1 == frames && !checkPng.empty()) {
        tissue::Image8 image(kWidth, kHeight, 4);
        glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, image.pixels.data());
        tissue::Image8 flipped(kWidth, kHeight, 4);  // GL rows are bottom first
        for (int y = 0; y < kHeight; ++y)
          std::memcpy(flipped.at(0, y), image.at(0, kHeight - 1 - y), std::size_t(kWidth) * 4);
        if (auto w = tissue::writePng(checkPng, flipped); !w)
          std::fprintf(stderr, "host_glfw: %s\n", w.error().message.c_str());
        const auto f = scene->instrumentForceN();
        std::printf("host_glfw: frame %d, tip at z = %.1f mm, force (%.3f, %.3f, %.3f) N\n", frames, tip.z,
                    f.x, f.y, f.z);
        status = check(flipped, camera, tip) > 0 ? 1 : status;
        if (!(f.z > 0.05f)) std::printf("host_glfw: FAILED: no force on the instrument\n"), status = 1;
      }
      glfwSwapBuffers(window);
      hostMs.push_back(whole.elapsedMs());
      glfwPollEvents();
    }
    for (const auto& [name, samples] :
         {std::pair{"step (simulate, mesh)", &stepMs}, std::pair{"render (upload, draw; CPU)", &renderMs},
          std::pair{"tissue per frame", &frameMs}, std::pair{"host frame to the swap", &hostMs}}) {
      const auto t = tissue::summarizeSamples(*samples);
      std::printf("host_glfw: %s: median %.2f ms, p99 %.2f ms, max %.2f ms over %zu frames\n", name, t.median,
                  t.p99, t.max, t.count);
    }
  }  // the scene goes while the host's context is current
  glfwDestroyWindow(window);
  glfwTerminate();
  return status;
}
