// The scene's side of the quality controller (budget.h): an organ's projected view, its offered
// options, and an option's renderer settings.
#include "tissue/scene/budget.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace tissue::scene {
namespace {

// The camera's axes and the projection to the image's [-1, 1]^2, shared by both footprints.
struct ViewBasis {
  Float3 f, r, u;
  float tanHalf, aspect;
  ViewBasis(const render::Camera& camera, int width, int height)
      : f(normalize(camera.target - camera.eye)),
        r(normalize(cross(f, camera.up))),
        u(cross(r, f)),
        tanHalf(std::tan(camera.verticalFovDeg * 3.14159265f / 360.0f)),
        aspect(float(width) / float(std::max(height, 1))) {}
  float depth(Float3 d) const { return dot(d, f); }  // d: from the eye, mm
  Float2 ndc(Float3 d, float z) const {
    return {dot(d, r) / (z * tanHalf * aspect), dot(d, u) / (z * tanHalf)};
  }
};

}  // namespace

quality::ObjectView organView(const Bounds3& b, const Mat4& model, const render::Camera& camera, int width,
                              int height) {
  quality::ObjectView v;
  const ViewBasis view(camera, width, height);
  float x0 = 1e30f, x1 = -1e30f, y0 = 1e30f, y1 = -1e30f;
  bool throughNear = false;
  for (int c = 0; c < 8; ++c) {
    const Float3 p =
        transformPoint(model, {c & 1 ? b.hi.x : b.lo.x, c & 2 ? b.hi.y : b.lo.y, c & 4 ? b.hi.z : b.lo.z});
    const Float3 d = p - camera.eye;
    const float z = view.depth(d);
    if (z < camera.nearMm) {
      throughNear = true;
      continue;
    }
    const auto [sx, sy] = view.ndc(d, z);
    x0 = std::min(x0, sx), x1 = std::max(x1, sx), y0 = std::min(y0, sy), y1 = std::max(y1, sy);
  }
  if (throughNear) x0 = y0 = -1.0f, x1 = y1 = 1.0f;  // the box reaches behind the near plane
  const float cx0 = std::clamp(x0, -1.0f, 1.0f), cx1 = std::clamp(x1, -1.0f, 1.0f);
  const float cy0 = std::clamp(y0, -1.0f, 1.0f), cy1 = std::clamp(y1, -1.0f, 1.0f);
  const double area =
      double(std::max(0.0f, cx1 - cx0)) * double(std::max(0.0f, cy1 - cy0)) / 4.0;  // of the image
  v.footprintPx = area * double(width) * double(height) * (throughNear ? 1.0 : 3.14159265 / 4.0);
  const Float3 centre = transformPoint(model, b.centre());
  v.distanceMm = double(length(centre - camera.eye));
  // The thinnest axis of the box as its surface normal (an organ lying on its back).
  const Float3 size = b.hi - b.lo;
  const std::array<Float3, 3> axes{Float3{1, 0, 0}, Float3{0, 1, 0}, Float3{0, 0, 1}};
  const int thin = size.x <= size.y && size.x <= size.z ? 0 : (size.y <= size.z ? 1 : 2);
  const Float3 n = normalize(transformDirection(model, axes[std::size_t(thin)]));
  const Float3 ray = normalize(centre - camera.eye);
  v.viewAngleDeg = double(std::acos(std::clamp(std::fabs(dot(n, ray)), 0.0f, 1.0f))) * 180.0 / 3.14159265;
  return v;
}

quality::ObjectView organView(const SurfaceMesh& mesh, const Bounds3& b, const Mat4& model,
                              const render::Camera& camera, int width, int height) {
  quality::ObjectView v = organView(b, model, camera, width, height);
  const std::size_t n = mesh.triangles.size();
  if (n == 0 || mesh.positions.empty() || v.footprintPx <= 0.0) return v;
  const ViewBasis view(camera, width, height);
  const std::size_t stride = (n + 1999) / 2000;
  double front = 0.0, back = 0.0;  // in NDC units (the image is 2 x 2)
  for (std::size_t t = 0; t < n; t += stride) {
    std::array<Float2, 3> q{};
    bool behind = false;
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t i = mesh.triangles[t][k];
      if (i >= mesh.positions.size()) return v;  // a malformed mesh: the bounds' estimate
      const Float3 d = transformPoint(model, mesh.positions[i]) - camera.eye;
      const float z = view.depth(d);
      if (z < camera.nearMm) {
        behind = true;
        break;
      }
      const Float2 p = view.ndc(d, z);
      q[k] = {std::clamp(p.x, -1.0f, 1.0f), std::clamp(p.y, -1.0f, 1.0f)};
    }
    if (behind) continue;
    const double area = 0.5 * (double(q[1].x - q[0].x) * double(q[2].y - q[0].y) -
                               double(q[2].x - q[0].x) * double(q[1].y - q[0].y));
    (area > 0.0 ? front : back) += std::fabs(area);
  }
  // At most the bounds' rectangle (the ellipse's 4 / pi; a box through the near plane: the image),
  // which bounds the layers a concave organ's triangles count twice.
  const double image = double(width) * double(height);
  const double rectangle = v.footprintPx >= image ? image : std::min(image, v.footprintPx * 4.0 / 3.14159265);
  const double px = std::max(front, back) * double(stride) / 4.0 * image;
  v.footprintPx = std::min(rectangle, px);
  return v;
}

std::vector<int> offeredOptions(const quality::QualityTable& table, const OrganAssets& organ) {
  std::vector<int> out;
  const auto methods = offeredMethods(organ);
  for (std::size_t i = 0; i < table.options.size(); ++i) {
    auto m = parseShadingMethod(table.options[i].method);
    if (m && std::find(methods.begin(), methods.end(), *m) != methods.end()) out.push_back(int(i));
  }
  return out;
}

Result<MethodChoices> choicesOfSetting(const quality::QualityOption& option, const MethodChoices& base) {
  MethodChoices c = base;
  const std::string& s = option.setting;
  const auto bad = [&] {
    return Error{"quality option " + option.method + " '" + s + "': not a setting name of the atlas"};
  };
  try {
    if (option.method == "separable") {
      const auto dash = s.rfind('-');
      if (dash == std::string::npos) return bad();
      c.kernel = s.substr(0, dash);
      c.taps = std::stoi(s.substr(dash + 1));
    } else if (option.method == "texture-space") {
      const auto g = s.find("g-");
      if (g == std::string::npos) return bad();
      c.gaussians = std::stoi(s.substr(0, g));
      c.cull = c.clip = c.depthSize = s.substr(g + 2) == "opt";
    } else if (option.method == "lit") {
      if (s == quality::kWrapSetting) c.litWrapFromOptics = true;
    } else if (option.method == "ray-march") {
      c.adaptive = s.rfind("adaptive", 0) == 0;
      const auto dash = s.rfind('-');
      c.samples = std::stoi(c.adaptive ? s.substr(dash + 1) : s);
    }
  } catch (...) {  // std::stoi: not a number
    return bad();
  }
  return c;
}

Result<render::MethodSettings> methodOfOption(const quality::QualityOption& option, const OrganAssets& organ,
                                              const OrganTextures& textures, const MethodChoices& base) {
  auto method = parseShadingMethod(option.method);
  if (!method) return method.error();
  auto choices = choicesOfSetting(option, base);
  if (!choices) return choices.error();
  auto settings = organMethod(*method, organ, textures, *choices);
  if (!settings) return settings.error();
  return settings;
}

FramePassCosts framePassCosts(const render::RenderTimings& timings, std::span<const double> weights) {
  FramePassCosts out;
  const std::size_t n = weights.size();
  out.objectMs.assign(n, 0.0);
  out.methodMs.assign(5, 0.0);
  const auto starts = [](const std::string& name, std::string_view p) { return name.rfind(p, 0) == 0; };
  for (const render::PassTiming& p : timings.passes) {
    if (p.object >= 0) {
      if (std::size_t(p.object) < n) out.objectMs[std::size_t(p.object)] += p.cpuMs;
      continue;
    }
    if (!p.issued.empty()) {
      // Each object its issue time; the rest of the pass by weight (llvmpipe: the fragments).
      double rest = p.cpuMs, total = 0.0;
      for (const auto& [object, ms] : p.issued) {
        rest -= ms;
        if (object >= 0 && std::size_t(object) < n) {
          out.objectMs[std::size_t(object)] += ms;
          total += std::max(0.0, weights[std::size_t(object)]);
        }
      }
      rest = std::max(0.0, rest);
      for (const auto& [object, ms] : p.issued) {
        if (object < 0 || std::size_t(object) >= n) continue;
        const double share =
            total > 0.0 ? std::max(0.0, weights[std::size_t(object)]) / total : 1.0 / double(p.issued.size());
        out.objectMs[std::size_t(object)] += rest * share;
      }
      continue;
    }
    int m = -1;
    if (p.name == "lit")
      m = 0;
    else if (starts(p.name, "separable"))
      m = 1;
    else if (starts(p.name, "texture"))
      m = 2;
    else if (starts(p.name, "ray"))
      m = 3;
    else if (starts(p.name, "parallax"))
      m = 4;
    if (m >= 0) out.methodMs[std::size_t(m)] += p.cpuMs;
  }
  return out;
}

}  // namespace tissue::scene
