// The scenes of the texture-space speed-up table (tsd_bench.h).
#include "tissue/studies/tsd_bench.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "tissue/core/statistics.h"
#include "tissue/core/stopwatch.h"

namespace tissue::studies {

render::Scene tsdBenchScene(Float3 target, float distance, float organSize, float rowLength) {
  render::Scene scene;
  const float dy = -0.35f, dz = -1.0f, n = std::hypot(dy, dz);
  scene.camera.target = target;
  scene.camera.eye = {target.x, target.y - dy / n * distance, target.z - dz / n * distance};
  scene.camera.nearMm = std::max(distance - organSize, distance * 0.05f);
  scene.camera.farMm = std::hypot(distance + organSize, rowLength);
  scene.lights[0].positionMm = {target.x + 0.6f * distance, target.y + 0.9f * distance, target.z + distance};
  return scene;
}

float TsdOrganRow::rowX(int i) const {
  return (float(i) - 0.5f * float(kMaxObjects - 1)) * 1.1f * widthMm;
}

render::Scene TsdOrganRow::sceneOf(int n, float distance, const render::TextureSpaceSettings& method) const {
  const int first = kMaxObjects / 2 - (n + 1) / 2;
  const float middle = 0.5f * (rowX(first) + rowX(first + n - 1));
  render::Scene scene = tsdBenchScene({middle, 0, 0}, distance, sizeMm, float(n) * 1.1f * widthMm);
  for (int i = first; i < first + n; ++i) {
    render::SceneObject object;
    object.mesh = meshes[std::size_t(i)];
    object.method = method;
    scene.objects.push_back(object);
  }
  return scene;
}

Result<TsdOrganRow> uploadOrganRow(render::Renderer& renderer, const TsdOrgan& organ) {
  TsdOrganRow row;
  const Float3 centre{0.5f * (organ.lo.x + organ.hi.x), 0.5f * (organ.lo.y + organ.hi.y),
                      0.5f * (organ.lo.z + organ.hi.z)};
  row.widthMm = organ.hi.x - organ.lo.x;
  row.sizeMm = std::hypot(row.widthMm, organ.hi.y - organ.lo.y, organ.hi.z - organ.lo.z);
  std::vector<Float3> positions(organ.mesh.positions.size());
  for (int i = 0; i < TsdOrganRow::kMaxObjects; ++i) {
    for (std::size_t v = 0; v < positions.size(); ++v) {
      const Float3 p = organ.mesh.positions[v];
      positions[v] = {p.x - centre.x + row.rowX(i), p.y - centre.y, p.z - centre.z};
    }
    render::MeshArrays arrays = organ.arrays();
    arrays.positions = positions;
    auto handle = renderer.createMesh(arrays);
    if (!handle) return handle.error();
    row.meshes.push_back(*handle);
  }
  return row;
}

namespace {

double median(const std::vector<double>& v) {
  return summarizeSamples(v).median;
}

// Renders `scene` 1 + repeats times (the first warms up allocations and shaders); the median ms.
Result<double> medianFrameMs(render::Renderer& renderer, const render::Scene& scene,
                             const TsdBenchConfig& c) {
  std::vector<double> ms;
  for (int rep = 0; rep <= c.repeats; ++rep) {
    Stopwatch watch;
    if (auto image = renderer.renderImage(scene, c.width, c.height); !image) return image.error();
    if (rep > 0) ms.push_back(watch.elapsedMs());
  }
  return median(ms);
}

// The report's tables and JSON from the measured figures.
StudyOutput tsdBenchOutput(const TsdBenchResult& r, const TsdOrgan& organ, const TsdBenchConfig& c,
                           double seconds) {
  nlohmann::json distances = nlohmann::json::array(), rows = nlohmann::json::array();
  for (float k : kTsdBenchDistances)
    distances.push_back(k * r.organSizeMm);
  Table speedup{{"organs"}, {}},
      speedupCsv{
          {"organs", "distance_organ_sizes", "distance_mm", "unoptimised_ms", "optimised_ms", "speedup"}, {}};
  for (float k : kTsdBenchDistances)
    speedup.header.push_back(general(k, 3) + " (" + fixed(k * r.organSizeMm, 0) + " mm)");
  for (std::size_t i = 0; i < r.speedup.size(); ++i) {
    const int objects = kTsdBenchObjects[i];
    speedup.rows.push_back({std::to_string(objects)});
    for (std::size_t j = 0; j < r.speedup[i].size(); ++j) {
      const float k = kTsdBenchDistances[j];
      speedup.rows.back().push_back(fixed(r.speedup[i][j], 2) + " (" + fixed(r.unoptimisedMs[i][j], 0) +
                                    " / " + fixed(r.optimisedMs[i][j], 0) + ")");
      speedupCsv.rows.push_back({std::to_string(objects), general(k, 3), fixed(k * r.organSizeMm, 1),
                                 general(r.unoptimisedMs[i][j]), general(r.optimisedMs[i][j]),
                                 general(r.speedup[i][j])});
    }
  }
  Table paper{{"heads"}, {}};
  for (float d : kJimenezTable1Distances)
    paper.header.push_back(general(d, 3));
  nlohmann::json paperJson = nlohmann::json::array();
  for (std::size_t i = 0; i < std::size(kJimenezTable1Speedup); ++i) {
    paper.rows.push_back({std::to_string(kTsdBenchObjects[i])});
    paperJson.push_back(kJimenezTable1Speedup[i]);
    for (double v : kJimenezTable1Speedup[i])
      paper.rows.back().push_back(fixed(v, 2));
  }
  Table accuracy{
      {"setting", "optimised", "ms", "map size", "texel RMS", "relative RMS", "interior relative RMS"}, {}};
  for (const TsdAccuracyRow& a : r.accuracy) {
    const std::string setting = std::to_string(a.gaussians) + "-gaussians";
    rows.push_back({{"setting", setting},
                    {"optimised", a.optimised},
                    {"ms", a.ms},
                    {"map_size", a.mapSize},
                    {"texel_rms", a.error.rms},
                    {"relative_rms", a.error.relative},
                    {"interior_relative_rms", a.error.interiorRelative}});
    accuracy.rows.push_back({setting, a.optimised ? "yes" : "no", fixed(a.ms, 1), std::to_string(a.mapSize),
                             general(a.error.rms, 4), fixed(a.error.relative, 4),
                             fixed(a.error.interiorRelative, 4)});
  }
  nlohmann::json json;
  json["objects"] = kTsdBenchObjects;
  json["distances"] = distances;
  json["distances_in_organ_sizes"] = kTsdBenchDistances;
  json["speedup"] = r.speedup;
  json["unoptimised_ms"] = r.unoptimisedMs;
  json["optimised_ms"] = r.optimisedMs;
  json["accuracy"] = {
      {"rows", rows}, {"reference_texels", r.referenceTexels}, {"reference_ms", r.referenceMs}};
  json["organ_size_mm"] = r.organSizeMm;
  json["mesh"] = c.mesh;
  json["atlas"] = organ.atlas;
  json["triangles"] = organ.mesh.triangles.size();
  json["width"] = c.width;
  json["height"] = c.height;
  json["map_size"] = c.mapSize;
  json["gaussians"] = c.gaussians;
  json["repeats"] = c.repeats;
  json["renderer"] =
      "the render pipeline (texture-space method), whole frames with composite, tone map and readback";
  json["gl_renderer"] = c.glRenderer;
  json["seconds"] = seconds;
  json["paper"] = {{"source", "Jimenez and Gutierrez 2008, Table 1 (GeForce 8800 GTX, 1920 x 1200, heads)"},
                   {"distances", kJimenezTable1Distances},
                   {"speedup", paperJson}};
  StudyOutput out;
  out.json = json.dump(2);
  out.summary = (r.speedup.empty() ? "" : markdownTable(speedup) + "\n") + markdownTable(accuracy);
  const std::string setup = std::to_string(c.width) + " x " + std::to_string(c.height) + " pixels, T_max " +
                            std::to_string(c.mapSize) + ", " + std::to_string(c.gaussians) +
                            " Gaussians, median of " + std::to_string(c.repeats) +
                            " frames per cell and path, " + c.glRenderer;
  std::string md = "# Texture-space diffusion: speed-up of the three optimisations\n\n" + c.mesh + " (" +
                   std::to_string(organ.mesh.triangles.size()) + " triangles), " + setup + ".\n\n";
  if (!r.speedup.empty())
    md +=
        "Speed-up (unoptimised ms / optimised ms) by organs and camera distance (organ diagonals, mm):\n\n" +
        markdownTable(speedup) +
        "\nJimenez and Gutierrez 2008, Table 1 (GeForce 8800 GTX, 1920 x 1200, heads):\n\n" +
        markdownTable(paper) + "\n";
  md +=
      "Accuracy (one organ, first distance) against the CPU convolution of the six-term profile over the "
      "surface (" +
      std::to_string(r.referenceTexels) + " texels):\n\n" + markdownTable(accuracy);
  out.report.add("tsd_bench.md", std::move(md));
  if (!r.speedup.empty()) out.report.add("tsd_bench_speedup.csv", csvTable(speedupCsv));
  out.report.add("tsd_bench_accuracy.csv", csvTable(accuracy));
  out.report.add("tsd_bench.json", out.json + "\n");
  if (c.chart && !r.speedup.empty()) {
    ReportChart chart{"tsd_bench_speedup.png",
                      {"Texture-space diffusion: speed-up of the three optimisations (" + c.glRenderer + ")",
                       "camera distance to the middle organ (organ diagonals)",
                       "speed-up (unoptimised ms / optimised ms)", true, false, 900, 600},
                      {}};
    for (std::size_t i = 0; i < r.speedup.size(); ++i) {
      const int objects = kTsdBenchObjects[i];
      inspect::ChartSeries line{
          std::to_string(objects) + (objects == 1 ? " organ" : " organs"), {}, {}, true};
      for (std::size_t j = 0; j < r.speedup[i].size(); ++j)
        line.x.push_back(double(kTsdBenchDistances[j])), line.y.push_back(r.speedup[i][j]);
      chart.series.push_back(std::move(line));
    }
    out.report.charts.push_back(std::move(chart));
  }
  return out;
}

}  // namespace

Result<TsdBenchResult> runTsdBench(render::Renderer& renderer, const TsdOrgan& organ,
                                   const TsdBenchConfig& c) {
  if (c.width <= 0 || c.height <= 0 || c.mapSize < 16 || c.repeats < 1)
    return Error{"the width, height and repeats must be positive and the map size at least 16"};
  auto gaussians = skinGaussians(c.skinTable, c.gaussians);
  if (!gaussians) return gaussians.error();
  auto six = skinGaussians(c.skinTable, 6);
  if (!six) return six.error();
  const Stopwatch total;
  // The row of organs (uploadOrganRow), 1.1 organ widths apart.
  auto row = uploadOrganRow(renderer, organ);
  if (!row) return row.error();
  TsdBenchResult out;
  out.organSizeMm = row->sizeMm;
  render::TextureSpaceSettings plain, optimised;
  plain.gaussians = optimised.gaussians = *gaussians;
  plain.mapSize = optimised.mapSize = c.mapSize;
  plain.cull = plain.clip = plain.depthSize = false;
  Image8 sixteen;  // the optimised frame of 16 organs at the second distance
  for (int objects : kTsdBenchObjects) {
    if (c.accuracyOnly) break;
    std::vector<double> rowS, rowP, rowO;
    for (float k : kTsdBenchDistances) {
      std::vector<double> tp, to;
      for (int rep = 0; rep <= c.repeats; ++rep) {    // repeat 0 warms up (allocations, shaders)
        for (const auto* s : {&plain, &optimised}) {  // alternated: load changes fall on both alike
          const render::Scene scene = row->sceneOf(objects, k * row->sizeMm, *s);
          Stopwatch watch;
          auto image = renderer.renderImage(scene, c.width, c.height);
          if (!image) return image.error();
          if (rep > 0) (s == &plain ? tp : to).push_back(watch.elapsedMs());
          if (c.image && s == &optimised && objects == 16 && k == kTsdBenchDistances[1] && rep == 0)
            sixteen = std::move(*image);
        }
      }
      const double p = median(tp), q = median(to);
      rowS.push_back(p / q), rowP.push_back(p), rowO.push_back(q);
    }
    out.speedup.push_back(rowS), out.unoptimisedMs.push_back(rowP), out.optimisedMs.push_back(rowO);
  }
  // Accuracy: one organ at the first distance. The reference convolves the unoptimised frame's
  // irradiance (read back) over the surface with the six-term skin profile (the material's own).
  render::TextureSpaceSettings reference = plain;
  reference.gaussians = *six;
  const float near = kTsdBenchDistances[0] * row->sizeMm;
  if (auto r = renderer.renderImage(row->sceneOf(1, near, reference), c.width, c.height); !r)
    return r.error();
  auto full = renderer.readTextureSpaceMaps();
  if (!full) return full.error();
  const render::SurfaceSamples samples = surfaceSamplesOf(*full);
  float cutoff = 0.0f;
  const auto table = skinProfileTable(*six, cutoff);
  out.referenceTexels = samples.positionMm.size();
  for (int n : {2, 4, 6}) {
    auto g = skinGaussians(c.skinTable, n);
    if (!g) return g.error();
    for (bool on : {false, true}) {
      render::TextureSpaceSettings s = on ? optimised : plain;
      s.gaussians = *g;
      auto ms = medianFrameMs(renderer, row->sceneOf(1, near, s), c);
      if (!ms) return ms.error();
      auto maps = renderer.readTextureSpaceMaps();
      if (!maps) return maps.error();
      const Stopwatch referenceWatch;
      const TexelError error = diffusedMapError(*maps, samples, table, cutoff);
      out.referenceMs += referenceWatch.elapsedMs();
      out.accuracy.push_back({n, on, *ms, maps->size, error});
    }
  }
  out.output = tsdBenchOutput(out, organ, c, total.elapsedMs() * 1e-3);
  if (c.image && sixteen.width > 0)
    out.output.report.images.push_back({"tsd_bench_16_organs.png", std::move(sixteen)});
  return out;
}

}  // namespace tissue::studies
