// tissue-datagen: regenerates the project's own data (meshes and layer textures); see docs/DATA.md.
#include <chrono>
#include <cstdio>
#include <thread>

#include <CLI/CLI.hpp>

#include "datagen.h"

int main(int argc, char** argv) {
  CLI::App app{"tissue-datagen: deterministic meshes and layer textures for tissue (see docs/DATA.md)"};
  app.require_subcommand(1);
  std::string outDir;
  int size = 1024;
  int threads = int(std::max(1u, std::thread::hardware_concurrency()));
  auto* meshes = app.add_subcommand("meshes", "write <out>/meshes/{patch,liver,tube}.obj (mm)");
  auto* textures = app.add_subcommand("textures", "write <out>/textures/<mesh>/*.png at size x size");
  auto* all = app.add_subcommand("all", "meshes and textures");
  for (CLI::App* sub : {meshes, textures, all}) {
    sub->add_option("--out", outDir, "output folder")->required();
  }
  for (CLI::App* sub : {textures, all}) {
    sub->add_option("--size", size, "texture width and height in texels")->check(CLI::Range(8, 8192));
    sub->add_option("--threads", threads, "worker threads (the output does not depend on it)")
        ->check(CLI::Range(1, 256));
  }
  CLI11_PARSE(app, argc, argv);

  const auto start = std::chrono::steady_clock::now();
  if (meshes->parsed() || all->parsed()) {
    if (auto ok = tissue::datagen::writeMeshes(outDir); !ok) {
      std::fprintf(stderr, "tissue-datagen: %s\n", ok.error().message.c_str());
      return 1;
    }
  }
  if (textures->parsed() || all->parsed()) {
    if (auto ok = tissue::datagen::writeTextures(outDir, size, threads); !ok) {
      std::fprintf(stderr, "tissue-datagen: %s\n", ok.error().message.c_str());
      return 1;
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("tissue-datagen: wrote %s in %.2f s\n", outDir.c_str(), seconds);
  return 0;
}
