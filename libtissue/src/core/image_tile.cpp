// Contact sheets of equal-sized images (image.h).
#include <algorithm>
#include <string>

#include "tissue/core/image.h"

namespace tissue {

Result<Image8> tileImages(std::span<const Image8> images, int columns, int shrink) {
  if (images.empty()) return Error{"tileImages: no images to tile"};
  if (columns < 1 || shrink < 1) return Error{"tileImages: columns and shrink must be at least 1"};
  const Image8& first = images[0];
  for (std::size_t i = 1; i < images.size(); ++i)
    if (images[i].width != first.width || images[i].height != first.height ||
        images[i].channels != first.channels)
      return Error{"tileImages: image " + std::to_string(i + 1) + " is not the size of the first (" +
                   std::to_string(first.width) + " x " + std::to_string(first.height) + ")"};
  const int w = first.width / shrink, h = first.height / shrink, n = int(images.size()), c = first.channels;
  if (w < 1 || h < 1) return Error{"tileImages: shrink " + std::to_string(shrink) + " leaves no pixels"};
  Image8 tiled(std::min(columns, n) * w, (n + columns - 1) / columns * h, c);
  const int area = shrink * shrink;
  for (int i = 0; i < n; ++i)
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        for (int k = 0; k < c; ++k) {
          int sum = 0;
          for (int dy = 0; dy < shrink; ++dy)
            for (int dx = 0; dx < shrink; ++dx)
              sum += images[std::size_t(i)].at(shrink * x + dx, shrink * y + dy)[k];
          tiled.at(i % columns * w + x, i / columns * h + y)[k] = std::uint8_t((sum + area / 2) / area);
        }
  return tiled;
}

}  // namespace tissue
