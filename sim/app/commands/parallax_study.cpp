// tissue-sim parallax-study --out DIR [--json]: where layered parallax (Oat 2006; Norberg 2010
// §2.2) fails, in numbers and images. The method looks the inner layer up at the tangent-plane
// offset of eq. 15-18 (layers "flat and parallel in tangent space"); the truth is the refracted
// view ray intersected with the actual inner layer, the surface pushed in by the depth along -N.
// Per view angle, on a plane (control), a sphere, the liver and the bowel tube: the distance (mm,
// on the outer surface) between the texel the method reads and the true one, and the fraction of
// rays that leave the surface before reaching the layer (the method still shows a layer there).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>

#include "../parallax_scene.h"
#include "command.h"
#include "output.h"
#include "tissue/render/parallax_math.h"
#include "tissue/subsurface/triangle_bvh.h"

namespace tissue::sim_app {
namespace {

using Vec = std::array<double, 3>;

struct StudyOptions {
  std::string out;          // folder for the images (created)
  int samplePoints = 1500;  // surface points per mesh and angle
  int imageWidth = 384;     // pixels
  int imageHeight = 288;    // pixels
};

constexpr float kAngles[] = {0.0f, 30.0f, 45.0f, 60.0f, 75.0f, 85.0f};  // degrees from the normal

struct Surface {
  std::string name, what;
  std::vector<Float3> positions, normals;  // mm, unit
  std::vector<Triangle> triangles;
  Vec sampleBoxMm{0.0, 0.0, 0.0};  // > 0: only points with |x|, |y|, |z| below (away from borders, poles)
};

Vec vec(Float3 a) {
  return {double(a.x), double(a.y), double(a.z)};
}
Vec add(Vec a, Vec b, double s = 1.0) {
  return {a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]};
}
double dot(Vec a, Vec b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Vec cross(Vec a, Vec b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec unit(Vec a) {
  const double l = std::sqrt(dot(a, a));
  return {a[0] / l, a[1] / l, a[2] / l};
}
// x T + y B + z N: from the tangent frame to world.
Vec frame(Vec T, Vec B, Vec N, double x, double y, double z) {
  return {x * T[0] + y * B[0] + z * N[0], x * T[1] + y * B[1] + z * N[1], x * T[2] + y * B[2] + z * N[2]};
}
double distance(Vec a, Vec b) {
  const Vec d = add(a, b, -1.0);
  return std::sqrt(dot(d, d));
}

// A grid of `n` x `n` quads, 300 mm square at z = 0 (+z out), or wrapped onto a sphere of radius
// `radius` (latitude-longitude, closed: the pole rows collapse to points).
Surface gridSurface(bool sphere, double radius, int n) {
  Surface s;
  s.name = sphere ? "sphere_r40" : "plane";
  s.what = sphere ? "sphere, radius 40 mm" : "flat plane (control: the method's assumption holds)";
  // The plane is 300 mm wide: no ray from the middle 200 mm reaches its border. The sphere's
  // lat-long grid is sampled away from its poles.
  s.sampleBoxMm = sphere ? Vec{0.0, 0.0, 0.95 * radius} : Vec{100.0, 100.0, 0.0};
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double u = double(i) / n, v = double(j) / n;
      if (sphere) {
        const double phi = 2.0 * std::numbers::pi * u, theta = std::numbers::pi * v;
        const Vec nrm{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
        s.positions.push_back({float(radius * nrm[0]), float(radius * nrm[1]), float(radius * nrm[2])});
        s.normals.push_back({float(nrm[0]), float(nrm[1]), float(nrm[2])});
      } else {
        s.positions.push_back({float(300.0 * (u - 0.5)), float(300.0 * (v - 0.5)), 0.0f});
        s.normals.push_back({0.0f, 0.0f, 1.0f});
      }
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const auto a = std::uint32_t(j * (n + 1) + i), b = a + 1, c = a + std::uint32_t(n + 1), d = c + 1;
      // Counter-clockwise seen from outside (+z for the plane, outward for the sphere).
      if (sphere) {
        s.triangles.push_back({a, c, b});
        s.triangles.push_back({b, c, d});
      } else {
        s.triangles.push_back({a, b, d});
        s.triangles.push_back({a, d, c});
      }
    }
  return s;
}

Result<Surface> organSurface(const char* name, const char* what) {
  auto organ = loadTsdOrgan(dataDir() / "meshes" / (std::string(name) + ".obj"), 1.0f);
  if (!organ) return organ.error();
  return Surface{name, what, organ->mesh.positions, organ->normals, organ->mesh.triangles};
}

// One (surface, depth, index, angle) cell of the study.
struct Cell {
  std::vector<double> errors;                     // mm, rays that reach the layer
  double parallaxOffset = 0.0, trueOffset = 0.0;  // mean mm from the shading point
  int misses = 0, samples = 0;
};

// Splitmix-style hash to [0, 1): a fixed azimuth per sample point.
double hash01(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return double((x ^ (x >> 31)) >> 11) / 9007199254740992.0;
}

Cell measure(const Surface& s, const subsurface::TriangleBvh& outer, const subsurface::TriangleBvh& inner,
             float depthMm, float index, float angleDeg, int points) {
  Cell cell;
  const float maxTransmission = render::ParallaxSettings{}.maxTransmissionMm;
  const std::size_t stride = std::max<std::size_t>(1, s.triangles.size() / std::size_t(points));
  const double a = double(angleDeg) * std::numbers::pi / 180.0;
  for (std::size_t v = 0; v < s.triangles.size(); v += stride) {
    // A point inside the triangle (never a vertex, where rays graze the mesh's edges), with the
    // interpolated normal.
    const Triangle& tri = s.triangles[v];
    double b1 = hash01(3 * v + 1), b2 = hash01(3 * v + 2);
    if (b1 + b2 > 1.0) b1 = 1.0 - b1, b2 = 1.0 - b2;
    b1 = 0.05 + 0.9 * b1, b2 = 0.05 + 0.9 * b2;
    const double b0 = std::max(1.0 - b1 - b2, 0.0);
    auto mix = [&](const std::vector<Float3>& f) {
      return add(add(Vec{b0 * double(f[tri[0]].x), b0 * double(f[tri[0]].y), b0 * double(f[tri[0]].z)},
                     vec(f[tri[1]]), b1),
                 vec(f[tri[2]]), b2);
    };
    const Vec P = mix(s.positions), N = unit(mix(s.normals));
    bool outside = false;
    for (int k = 0; k < 3; ++k)
      outside = outside || (s.sampleBoxMm[k] > 0.0 && std::abs(P[k]) > s.sampleBoxMm[k]);
    if (outside) continue;
    const Vec T = unit(cross(std::abs(N[0]) < 0.9 ? Vec{1, 0, 0} : Vec{0, 1, 0}, N)), B = cross(N, T);
    const double phi = 2.0 * std::numbers::pi * hash01(3 * v);
    const Float3 viewTangent{float(std::sin(a) * std::cos(phi)), float(std::sin(a) * std::sin(phi)),
                             float(std::cos(a))};
    // The method: eq. 15-18 with the geometric normal, the offset in the tangent plane.
    const auto lookup = render::transmissionLookup(viewTangent, {0, 0, 1}, index, depthMm, maxTransmission);
    const Vec offset = frame(T, B, N, double(lookup.offsetMm.x), double(lookup.offsetMm.y), 0.0);
    // ... read through the UV Jacobian at P: the surface point under P + offset (along -N).
    const double h = std::sqrt(dot(offset, offset)) + 1.0;
    const auto down = outer.intersect(add(add(P, offset), N, h), {-N[0], -N[1], -N[2]}, 0.0, 3.0 * h);
    // The truth: the refracted ray to the inner surface (the outer one moved by -d N), unless it
    // leaves the outer surface first.
    const Vec t = unit(
        frame(T, B, N, double(lookup.direction.x), double(lookup.direction.y), double(lookup.direction.z)));
    const auto hit = inner.intersect(P, t, 0.0, 1e4);
    ++cell.samples;
    if (!down) continue;  // the lookup falls off an open border: not a sample
    const bool exits = !hit || outer.intersect(P, t, 1e-3, hit->t).has_value();
    if (exits) {
      ++cell.misses;
      continue;
    }
    // The inner surface shares the outer one's triangles: the hit's barycentrics on the outer
    // triangle are the texel the true inner layer shows.
    auto at = [&](const subsurface::RayHit& r) {
      const Triangle& hitTriangle = s.triangles[r.triangle];
      const Vec p0 = vec(s.positions[hitTriangle[0]]);
      const double w0 = 1.0 - r.b1 - r.b2;
      return add(add(Vec{p0[0] * w0, p0[1] * w0, p0[2] * w0}, vec(s.positions[hitTriangle[1]]), r.b1),
                 vec(s.positions[hitTriangle[2]]), r.b2);
    };
    const Vec truth = at(*hit), method = at(*down);
    cell.errors.push_back(distance(truth, method));
    cell.parallaxOffset += distance(method, P);
    cell.trueOffset += distance(truth, P);
  }
  return cell;
}

nlohmann::json cellJson(const Cell& c) {
  nlohmann::json j;
  std::vector<double> e = c.errors;
  std::sort(e.begin(), e.end());
  const double n = double(e.size());
  double mean = 0.0;
  for (double x : e)
    mean += x;
  j["samples"] = c.samples;
  j["reached"] = e.size();
  j["miss_fraction"] = c.samples ? double(c.misses) / double(c.samples) : 0.0;
  j["mean_error_mm"] = e.empty() ? -1.0 : mean / n;
  j["p95_error_mm"] = e.empty() ? -1.0 : e[std::min(e.size() - 1, std::size_t(0.95 * n))];
  j["max_error_mm"] = e.empty() ? -1.0 : e.back();
  j["mean_parallax_offset_mm"] = e.empty() ? -1.0 : c.parallaxOffset / n;
  j["mean_true_offset_mm"] = e.empty() ? -1.0 : c.trueOffset / n;
  return j;
}

// Images of the patch seen at angles from its normal: the inner vessels' shift and, at grazing
// angles, the eq. 19 fade to the outer layer.
Result<nlohmann::json> renderImages(const StudyOptions& o) {
  ParallaxOptions options;
  options.layerDepthMm = 3.0f;
  options.settings.opacity = 0.3f;
  auto loaded = loadParallaxScene(dataDir() / "meshes" / "patch.obj", 1.0f,
                                  float(o.imageWidth) / float(o.imageHeight), 4, options);
  if (!loaded) return loaded.error();
  ParallaxScene& p = *loaded;
  p.scene.lights[0].type = render::LightType::Directional;
  p.scene.lights[0].direction = {-0.3f, -0.2f, -1.0f};
  nlohmann::json files = nlohmann::json::array();
  for (const float angle : {0.0f, 45.0f, 75.0f, 85.0f}) {
    const float a = angle * std::numbers::pi_v<float> / 180.0f;
    p.scene.camera =
        render::frameBoundingBox(p.organ.lo, p.organ.hi, float(o.imageWidth) / float(o.imageHeight),
                                 {-std::sin(a), 0.0f, -std::cos(a)});
    // Closer than the bounding-sphere fit: the patch fills the frame seen from above.
    render::Camera& c = p.scene.camera;
    c.eye = {c.target.x + 0.6f * (c.eye.x - c.target.x), c.target.y + 0.6f * (c.eye.y - c.target.y),
             c.target.z + 0.6f * (c.eye.z - c.target.z)};
    c.nearMm *= 0.3f;
    auto image = p.renderer->renderImage(p.scene, o.imageWidth, o.imageHeight);
    if (!image) return image.error();
    const auto file =
        std::filesystem::path(o.out) / ("parallax_patch_" + std::to_string(int(angle)) + "deg.png");
    if (auto w = writePng(file, *image); !w) return w.error();
    files.push_back(file.string());
  }
  return files;
}

int run(const StudyOptions& o, const GlobalOptions& global) {
  const char* cmd = "parallax-study";
  std::error_code ec;
  std::filesystem::create_directories(o.out, ec);
  if (ec) return fail(cmd, "--out " + o.out + ": cannot create the folder: " + ec.message());
  std::vector<Surface> surfaces = {gridSurface(false, 0.0, 100), gridSurface(true, 40.0, 160)};
  for (auto [name, what] : {std::pair{"liver", "liver (rest shape; curvature radii ~30-100 mm)"},
                            std::pair{"tube", "bowel tube, radius 8-12 mm (high curvature)"}}) {
    auto s = organSurface(name, what);
    if (!s) return fail(cmd, std::string(name) + ": " + s.error().message);
    surfaces.push_back(std::move(*s));
  }
  nlohmann::json rows = nlohmann::json::array();
  for (const Surface& s : surfaces) {
    const subsurface::TriangleBvh outer(s.positions, s.triangles);
    for (const float depth : {1.0f, 3.0f}) {
      std::vector<Float3> pushed(s.positions.size());
      for (std::size_t i = 0; i < pushed.size(); ++i)
        pushed[i] = {s.positions[i].x - depth * s.normals[i].x, s.positions[i].y - depth * s.normals[i].y,
                     s.positions[i].z - depth * s.normals[i].z};
      const subsurface::TriangleBvh inner(pushed, s.triangles);
      for (const float index : {1.0f, 1.4f}) {
        nlohmann::json row;
        row["surface"] = s.name;
        row["what"] = s.what;
        row["depth_mm"] = depth;
        row["refractive_index"] = index;
        nlohmann::json cells = nlohmann::json::array();
        for (const float angle : kAngles) {
          nlohmann::json c = cellJson(measure(s, outer, inner, depth, index, angle, o.samplePoints));
          c["view_angle_deg"] = angle;
          cells.push_back(c);
        }
        row["angles"] = cells;
        rows.push_back(row);
      }
    }
  }
  auto images = renderImages(o);
  if (!images) return fail(cmd, "images: " + images.error().message);
  nlohmann::json out;
  out["results"] = rows;
  out["images"] = *images;
  out["max_transmission_mm"] = render::ParallaxSettings{}.maxTransmissionMm;
  if (global.json) {
    printResult(global, out);
    return 0;
  }
  std::printf("mean lookup error, mm (miss %% where rays leave before the layer)\n%-11s %5s %4s", "surface",
              "d mm", "n");
  for (const float a : kAngles)
    std::printf(" %13.0f", double(a));
  std::printf("\n");
  for (const auto& r : rows) {
    std::printf("%-11s %5.1f %4.1f", r["surface"].get<std::string>().c_str(), r["depth_mm"].get<double>(),
                r["refractive_index"].get<double>());
    for (const auto& c : r["angles"]) {  // "-": no ray reached the layer
      const double miss = 100.0 * c["miss_fraction"].get<double>();
      if (c["reached"].get<int>() == 0)
        std::printf(" %6s (%3.0f%%)", "-", miss);
      else
        std::printf(" %6.3f (%3.0f%%)", c["mean_error_mm"].get<double>(), miss);
    }
    std::printf("\n");
  }
  for (const auto& f : *images)
    std::printf("wrote %s\n", f.get<std::string>().c_str());
  return 0;
}

}  // namespace

void registerParallaxStudyCommand(CLI::App& app, const GlobalOptions& global, int& exitCode) {
  auto o = std::make_shared<StudyOptions>();
  auto* cmd = app.add_subcommand("parallax-study",
                                 "where layered parallax fails: lookup error (mm) against the refracted ray "
                                 "meeting the true inner layer, per view angle, on flat and curved meshes");
  cmd->add_option("--out", o->out, "folder for the images (created)")->required();
  cmd->add_option("--points", o->samplePoints, "surface points per mesh and angle (default 1500)");
  cmd->callback([o, &global, &exitCode] { exitCode = run(*o, global); });
}

}  // namespace tissue::sim_app
