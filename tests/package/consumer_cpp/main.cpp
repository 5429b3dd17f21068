// A host of the installed tissue: loads a surface mesh, creates a headless GL context and a
// renderer, renders one lit frame and checks that the organ is in it (not a blank image).
//   tissue_consumer <mesh.obj> <out.png>
// Exit 0 on success; one line on stderr and exit 1 on any failure.
#include <tissue/tissue.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <set>
#include <string>

namespace {

int fail(const std::string& message) {
  std::cerr << "tissue_consumer: " << message << "\n";
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) return fail("usage: tissue_consumer <mesh> <out.png>");
  const std::filesystem::path meshPath = argv[1], pngPath = argv[2];

  // Mesh module: load, then normals, tangent frames and local planes of the deformable surface.
  auto mesh = tissue::mesh::loadMesh(meshPath);
  if (!mesh) return fail(mesh.error().message);
  auto surface = tissue::mesh::DeformableSurface::create(std::move(*mesh));
  if (!surface) return fail(surface.error().message);

  // A context of the installed library (EGL, else OSMesa) and a renderer on it.
  auto context = tissue::context::createHeadlessContext();
  if (!context) return fail(context.error().message);
  auto renderer = tissue::render::Renderer::create((*context)->procAddressFunction());
  if (!renderer) return fail(renderer.error().message);
  auto handle = renderer->createMesh({.positions = surface->positions(),
                                      .normals = surface->normals(),
                                      .tangents = surface->tangents(),
                                      .uvs = surface->uvs(),
                                      .triangles = surface->triangles(),
                                      .planes = surface->planes()});
  if (!handle) return fail(handle.error().message);

  tissue::Float3 lo = surface->positions()[0], hi = lo;
  for (const tissue::Float3& p : surface->positions()) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  constexpr int kWidth = 160, kHeight = 120;
  tissue::render::Scene scene;
  scene.camera = tissue::render::frameBoundingBox(lo, hi, float(kWidth) / float(kHeight));
  tissue::render::SceneObject object;
  object.mesh = *handle;
  scene.objects.push_back(object);
  auto image = renderer->renderImage(scene, kWidth, kHeight);
  if (!image) return fail(image.error().message);
  if (auto written = tissue::writePng(pngPath, *image); !written) return fail(written.error().message);

  // Non-blank: the organ covers a good part of the frame, shaded (many distinct colours), not flat.
  const auto bg = [&](float c) { return int(c * 255.0f + 0.5f); };
  const int bgR = bg(scene.background.x), bgG = bg(scene.background.y), bgB = bg(scene.background.z);
  int covered = 0;
  std::set<int> colours;
  for (int y = 0; y < image->height; ++y)
    for (int x = 0; x < image->width; ++x) {
      const std::uint8_t* px = image->at(x, y);
      if (std::abs(px[0] - bgR) + std::abs(px[1] - bgG) + std::abs(px[2] - bgB) > 12) {
        ++covered;
        colours.insert((px[0] << 16) | (px[1] << 8) | px[2]);
      }
    }
  const double coverage = double(covered) / double(kWidth * kHeight);
  std::cout << "backend " << (*context)->info().backend << " (" << (*context)->info().renderer << "), "
            << surface->positions().size() << " vertices, coverage " << coverage << ", " << colours.size()
            << " colours, rest positions sha256 "
            << tissue::scene::positionsSha256(surface->geometricRestPositions()).substr(0, 12) << "\n";
  if (coverage < 0.05)
    return fail("blank frame: the organ covers " + std::to_string(coverage * 100) + "% of it");
  if (colours.size() < 50) return fail("flat frame: " + std::to_string(colours.size()) + " distinct colours");
  return 0;
}
