#pragma once
/// \file
/// 8-bit images in memory and their PNG files (stb inside core/src/image_io.cpp only).

#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

#include "tissue/core/result.h"

namespace tissue {

/// An 8-bit image, rows top to bottom, `channels` interleaved bytes per pixel (1 to 4).
struct Image8 {
  int width = 0;
  int height = 0;
  int channels = 4;
  std::vector<std::uint8_t> pixels;  ///< width * height * channels bytes

  Image8() = default;
  Image8(int w, int h, int c) : width(w), height(h), channels(c), pixels(std::size_t(w) * h * c, 0) {}

  std::uint8_t* at(int x, int y) { return pixels.data() + (std::size_t(y) * width + x) * channels; }
  const std::uint8_t* at(int x, int y) const {
    return pixels.data() + (std::size_t(y) * width + x) * channels;
  }
};

/// Writes `image` as PNG, atomically.
Result<void> writePng(const std::filesystem::path& path, const Image8& image);

/// Reads a PNG (or any format stb reads) keeping its channel count unless `forceChannels` is 1-4.
Result<Image8> readImage(const std::filesystem::path& path, int forceChannels = 0);

/// Flips rows in place (GL reads bottom-up).
void flipVertically(Image8& image);

/// `images` (equal sizes and channel counts) tiled `columns` a row, left to right and top to
/// bottom, each shrunk `shrink` times by a box filter (1: full size), for contact sheets of
/// frames or methods. Errors on none, mismatched sizes, columns < 1 or shrink < 1.
Result<Image8> tileImages(std::span<const Image8> images, int columns, int shrink = 1);

}  // namespace tissue
