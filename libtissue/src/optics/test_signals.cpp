// The error measures' test signals (kernel_error.h; Freude §6.2, §5.3, eq. 5.14).
#include <cmath>
#include <numbers>

#include "tissue/optics/kernel_error.h"

namespace tissue::optics {
namespace {

// Disc centred at (0.3, 0.5), radius 0.15, and two 0.2-wide squares tilted by 30 degrees that share
// an edge, right of it (unit-square coordinates).
double circleAndSquares(double u, double v) {
  if (std::hypot(u - 0.3, v - 0.5) < 0.15) return 1.0;
  const double c = std::cos(std::numbers::pi / 6), s = std::sin(std::numbers::pi / 6);
  for (int k = 0; k < 2; ++k) {
    const double cx = 0.62 + k * 0.2 * c, cy = 0.45 + k * 0.2 * s;  // adjacent along the tilted x
    const double lx = (u - cx) * c + (v - cy) * s, ly = -(u - cx) * s + (v - cy) * c;
    if (std::abs(lx) < 0.1 && std::abs(ly) < 0.1) return 1.0;
  }
  return 0.0;
}

// A bumpy height field lit by a Lambertian light from the upper left, with a soft-edged cast shadow
// over the lower right (Freude Fig. 5.10's "shaded skin patch", synthetic).
double shadedPatch(double u, double v) {
  const double k = 2.0 * std::numbers::pi;
  const double dhdu =
      0.05 * k * 3 * std::cos(k * 3 * u) * std::cos(k * 2 * v) + 0.03 * k * 7 * std::cos(k * 7 * u);
  const double dhdv =
      -0.05 * k * 2 * std::sin(k * 3 * u) * std::sin(k * 2 * v) + 0.02 * k * 5 * std::cos(k * 5 * v);
  const double nx = -dhdu, ny = -dhdv, nz = 1.0, nl = std::sqrt(nx * nx + ny * ny + nz * nz);
  const double lx = -0.5, ly = -0.4, lz = 0.77, ll = std::sqrt(lx * lx + ly * ly + lz * lz);
  double e = std::max(0.0, (nx * lx + ny * ly + nz * lz) / (nl * ll));
  if (u + 0.6 * v + 0.1 * std::sin(k * 2 * v) > 1.1) e *= 0.1;  // the cast shadow
  return std::min(1.0, e);
}

}  // namespace

SignalImage makeTestSignal(TestSignal signal, int size) {
  SignalImage img;
  img.size = size;
  img.value.resize(static_cast<std::size_t>(size * size));
  const int sub = signal == TestSignal::CircleAndSquares ? 4 : 1;  // antialiased shapes
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      double sum = 0;
      for (int sy = 0; sy < sub; ++sy) {
        for (int sx = 0; sx < sub; ++sx) {
          const double u = (x + (sx + 0.5) / sub) / size, v = (y + (sy + 0.5) / sub) / size;
          switch (signal) {
            case TestSignal::VerticalEdge:
              sum += x < size / 2 ? 1.0 : 0.0;
              break;
            case TestSignal::CircleAndSquares:
              sum += circleAndSquares(u, v);
              break;
            case TestSignal::ShadedPatch:
              sum += shadedPatch(u, v);
              break;
            case TestSignal::AdditivelySeparable:  // E1(x) + E2(y): an edge plus horizontal stripes
              sum += 0.5 * (x < size / 3 ? 1.0 : 0.0) +
                     0.25 * (1.0 + std::sin(2.0 * std::numbers::pi * 5.0 * v));
              break;
          }
        }
      }
      img.value[static_cast<std::size_t>(y * size + x)] = sum / (sub * sub);
    }
  }
  return img;
}

}  // namespace tissue::optics
