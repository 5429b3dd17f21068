// Per-frame costs of the mesh module's shading update on the liver (data/meshes/liver.obj):
// vertex normals, tangent frames, the incremental plane re-fit after a 5% poke, and the whole
// DeformableSurface::update. Times are wall-clock ms per call; the fast paths run with 1 and
// 2 threads (the Arg).

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numeric>
#include <vector>

#include "tissue/mesh/deformable_surface.h"
#include "tissue/mesh/load_mesh.h"
#include "tissue/mesh/tangent_frames.h"
#include "tissue/mesh/vertex_normals.h"
#include "tissue/mesh/worker_pool.h"

namespace tissue::mesh {
namespace {

/// The liver and a poked copy of its geometric positions, loaded once.
struct Liver {
  SurfaceMesh mesh;
  std::vector<Float3> geoRest;
  std::vector<Triangle> geoTriangles;
  std::vector<Float3> geoPoked;  ///< 5% of the vertices, around the top one, pushed in (up to 8 mm)
  std::vector<Float3> normals;   ///< #render vertices, at rest
};

const Liver& liver() {
  static const Liver l = [] {
    Liver out;
    auto loaded = loadMesh(TISSUE_BENCH_DATA_DIR "/meshes/liver.obj", {.requireUvs = true});
    if (!loaded) {
      std::fprintf(stderr, "tissue_mesh_bench: %s\n", loaded.error().message.c_str());
      std::exit(1);
    }
    out.mesh = std::move(*loaded);
    out.geoRest = geometricPositionsOf(out.mesh);
    out.geoTriangles = geometricTrianglesOf(out.mesh);
    std::vector<Float3> geoNormals(out.geoRest.size());
    computeVertexNormals(out.geoRest, out.geoTriangles, geoNormals);
    out.normals.resize(out.mesh.positions.size());
    for (std::size_t i = 0; i < out.normals.size(); ++i)
      out.normals[i] = geoNormals[out.mesh.geometricIndex[i]];
    // Poke: the 5% of vertices nearest the topmost one move against their normal, with a
    // cosine falloff from the site.
    const auto& p = out.geoRest;
    const std::size_t site = std::size_t(
        std::max_element(p.begin(), p.end(), [](Float3 a, Float3 b) { return a.z < b.z; }) - p.begin());
    const auto dist2 = [&](std::size_t i) {
      const float dx = p[i].x - p[site].x, dy = p[i].y - p[site].y, dz = p[i].z - p[site].z;
      return dx * dx + dy * dy + dz * dz;
    };
    std::vector<std::size_t> order(p.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    const std::size_t moved = p.size() / 20;
    std::nth_element(order.begin(), order.begin() + std::ptrdiff_t(moved), order.end(),
                     [&](std::size_t a, std::size_t b) { return dist2(a) < dist2(b); });
    const float radius2 = dist2(order[moved]);
    out.geoPoked = p;
    for (std::size_t j = 0; j < moved; ++j) {
      const std::size_t i = order[j];
      const float depth = 8.0f * 0.5f * (1.0f + std::cos(3.14159265f * std::sqrt(dist2(i) / radius2)));
      out.geoPoked[i] = {p[i].x - depth * geoNormals[i].x, p[i].y - depth * geoNormals[i].y,
                         p[i].z - depth * geoNormals[i].z};
    }
    return out;
  }();
  return l;
}

// Normals and tangents through the original free functions (topology built per call).
void BM_VertexNormalsFromScratch(benchmark::State& state) {
  const Liver& l = liver();
  std::vector<Float3> normals(l.geoRest.size());
  for (auto _ : state) {
    computeVertexNormals(l.geoPoked, l.geoTriangles, normals);
    benchmark::DoNotOptimize(normals.data());
  }
}
BENCHMARK(BM_VertexNormalsFromScratch)->Unit(benchmark::kMillisecond);

void BM_TangentFramesFromScratch(benchmark::State& state) {
  const Liver& l = liver();
  std::vector<Float4> tangents(l.mesh.positions.size());
  for (auto _ : state) {
    computeTangentFrames(l.mesh.positions, l.mesh.uvs, l.mesh.triangles, l.normals, tangents,
                         l.mesh.geometricIndex);
    benchmark::DoNotOptimize(tangents.data());
  }
}
BENCHMARK(BM_TangentFramesFromScratch)->Unit(benchmark::kMillisecond);

// The fast paths with precomputed topology on a pool of state.range(0) threads: the
// triangle pass (normal, angles, and UV gradients as the update computes them) plus the
// per-vertex gather.
void BM_VertexNormalsPrecomputed(benchmark::State& state) {
  const Liver& l = liver();
  WorkerPool pool(unsigned(state.range(0)));
  const VertexCorners corners = buildVertexCorners(l.geoTriangles, l.geoRest.size());
  const TangentTopology topology = buildTangentTopology(l.mesh.uvs, l.mesh.triangles, l.mesh.geometricIndex);
  std::vector<TriangleGeometry> geometry(l.geoTriangles.size());
  std::vector<Float3> normals(l.geoRest.size());
  for (auto _ : state) {
    pool.parallelFor(geometry.size(), 4096, [&](std::size_t b, std::size_t e) {
      computeTriangleGeometry(l.geoPoked, l.geoTriangles, topology.uvBases, b, e, geometry);
    });
    computeVertexNormals(geometry, corners, normals, &pool);
    benchmark::DoNotOptimize(normals.data());
  }
}
BENCHMARK(BM_VertexNormalsPrecomputed)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

void BM_TangentFramesPrecomputed(benchmark::State& state) {
  const Liver& l = liver();
  WorkerPool pool(unsigned(state.range(0)));
  const TangentTopology topology = buildTangentTopology(l.mesh.uvs, l.mesh.triangles, l.mesh.geometricIndex);
  std::vector<TriangleGeometry> geometry(l.mesh.triangles.size());
  computeTriangleGeometry(l.mesh.positions, l.mesh.triangles, topology.uvBases, 0, geometry.size(), geometry);
  std::vector<Float4> tangents(l.mesh.positions.size());
  for (auto _ : state) {
    computeTangentFrames(geometry, topology, l.normals, tangents, &pool);
    benchmark::DoNotOptimize(tangents.data());
  }
}
BENCHMARK(BM_TangentFramesPrecomputed)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

// The incremental plane re-fit: every call moves the poked 5% (alternately in and out).
void BM_PlaneRefitAfterPoke(benchmark::State& state) {
  const Liver& l = liver();
  IncrementalPlaneFitter fitter(l.geoRest, l.geoTriangles, {});
  std::vector<Float3> normals(l.geoRest.size()), pokedNormals(l.geoRest.size());
  computeVertexNormals(l.geoRest, l.geoTriangles, normals);
  computeVertexNormals(l.geoPoked, l.geoTriangles, pokedNormals);
  fitter.fitAll(l.geoRest, normals);
  bool poked = false;
  for (auto _ : state) {
    poked = !poked;
    benchmark::DoNotOptimize(
        fitter.update(poked ? l.geoPoked : l.geoRest, poked ? pokedNormals : normals).refittedPlanes);
  }
}
BENCHMARK(BM_PlaneRefitAfterPoke)->Unit(benchmark::kMillisecond);

// The whole DeformableSurface::update (positions, normals, planes, tangents), alternately
// poked and released, with the per-phase means as counters (ms).
void BM_SurfaceUpdate(benchmark::State& state) {
  const Liver& l = liver();
  auto surface = DeformableSurface::create(l.mesh, {}, unsigned(state.range(0)));
  if (!surface) {
    state.SkipWithError(surface.error().message.c_str());
    return;
  }
  bool poked = false;
  SurfaceUpdateStats sum;
  for (auto _ : state) {
    poked = !poked;
    const auto s = surface->update(poked ? l.geoPoked : l.geoRest);
    sum.gatherMs += s.gatherMs, sum.normalsMs += s.normalsMs, sum.planesMs += s.planesMs,
        sum.tangentsMs += s.tangentsMs;
  }
  const double n = double(std::max<benchmark::IterationCount>(state.iterations(), 1));
  state.counters["gather_ms"] = sum.gatherMs / n;
  state.counters["normals_ms"] = sum.normalsMs / n;
  state.counters["planes_ms"] = sum.planesMs / n;
  state.counters["tangents_ms"] = sum.tangentsMs / n;
}
BENCHMARK(BM_SurfaceUpdate)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace tissue::mesh

BENCHMARK_MAIN();
