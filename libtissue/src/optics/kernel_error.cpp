// Kernel-space and image-space errors of separable kernels (kernel_error.h; Freude §5.1, §6.2).
#include "tissue/optics/kernel_error.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <unsupported/Eigen/FFT>

namespace tissue::optics {
namespace {

using Complex = std::complex<double>;
using Grid = std::vector<Complex>;  // row-major L x L

// In-place 2D FFT of an L x L grid: rows, then columns.
void fft2(Eigen::FFT<double>& fft, Grid& g, int l, bool inverse) {
  std::vector<Complex> in(static_cast<std::size_t>(l)), out;
  for (int pass = 0; pass < 2; ++pass) {
    for (int i = 0; i < l; ++i) {
      for (int j = 0; j < l; ++j)
        in[static_cast<std::size_t>(j)] =
            pass == 0 ? g[static_cast<std::size_t>(i * l + j)] : g[static_cast<std::size_t>(j * l + i)];
      if (inverse)
        fft.inv(out, in);
      else
        fft.fwd(out, in);
      for (int j = 0; j < l; ++j)
        (pass == 0 ? g[static_cast<std::size_t>(i * l + j)] : g[static_cast<std::size_t>(j * l + i)]) =
            out[static_cast<std::size_t>(j)];
    }
  }
}

int clampIndex(int i, int n) {
  return std::clamp(i, 0, n - 1);
}

// Linear interpolation of row (or column) data at fractional index f, clamped to the edge.
double sampleLinear(const double* data, int n, int stride, double f) {
  const double fl = std::floor(f);
  const double t = f - fl;
  const int i0 = static_cast<int>(fl);
  return (1.0 - t) * data[clampIndex(i0, n) * stride] + t * data[clampIndex(i0 + 1, n) * stride];
}

// One 1D pass of `taps` along x (stride 1) or y (stride n), per channel weight `channel`.
std::vector<double> pass(const std::vector<double>& src, int n, const std::vector<KernelTap>& taps,
                         int channel, double cellMm, bool vertical) {
  std::vector<double> dst(src.size(), 0.0);
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      const double* line =
          vertical ? &src[static_cast<std::size_t>(x)] : &src[static_cast<std::size_t>(y * n)];
      const int stride = vertical ? n : 1;
      const int at = vertical ? y : x;
      double sum = 0;
      for (const auto& t : taps) {
        const double w = channelOf(t.weight, channel);
        sum += w * sampleLinear(line, n, stride, at + static_cast<double>(t.offsetMm) / cellMm);
      }
      dst[static_cast<std::size_t>(y * n + x)] = sum;
    }
  }
  return dst;
}

}  // namespace

std::array<double, kChannels> kernelSpaceRms(const GroundTruthKernel& truth, const SeparableKernel& kernel) {
  const int n = truth.size();
  std::array<double, kChannels> rms{};
  for (int c = 0; c < kChannels; ++c) {
    const auto ch = static_cast<std::size_t>(c);
    double sum = 0;
    for (int y = 0; y < n; ++y) {
      for (int x = 0; x < n; ++x) {
        double a = 0;  // A = sum_i sign_i a_i a_i^T (Freude eq. 5.10)
        for (const auto& comp : kernel.components) {
          const double sign = channelOf(comp.sign, c);
          a += sign * comp.dense[ch][static_cast<std::size_t>(y)] *
               comp.dense[ch][static_cast<std::size_t>(x)];
        }
        const double e = truth.at(c, y, x) - a;
        sum += e * e;
      }
    }
    rms[ch] = std::sqrt(sum / (static_cast<double>(n) * n));
  }
  return rms;
}

ImageRgb convolveExact(const GroundTruthKernel& truth, const SignalImage& signal) {
  const int n = signal.size, h = truth.halfCells, m = truth.size();
  int l = 1;
  while (l < n + 2 * h)
    l *= 2;
  Eigen::FFT<double> fft;
  // The signal padded by h on each side with its edge values (clamp to edge), zero beyond.
  Grid s(static_cast<std::size_t>(l * l), Complex(0.0));
  for (int y = 0; y < n + 2 * h; ++y)
    for (int x = 0; x < n + 2 * h; ++x)
      s[static_cast<std::size_t>(y * l + x)] =
          signal.value[static_cast<std::size_t>(clampIndex(y - h, n) * n + clampIndex(x - h, n))];
  fft2(fft, s, l, false);
  ImageRgb out;
  for (int c = 0; c < kChannels; ++c) {
    Grid k(static_cast<std::size_t>(l * l), Complex(0.0));
    for (int y = 0; y < m; ++y)
      for (int x = 0; x < m; ++x)
        k[static_cast<std::size_t>(y * l + x)] = truth.at(c, y, x);
    fft2(fft, k, l, false);
    for (std::size_t i = 0; i < k.size(); ++i)
      k[i] *= s[i];
    fft2(fft, k, l, true);
    // Output pixel (y, x) sits at (y + 2h, x + 2h) of the circular convolution (no wrap-around).
    auto& img = out[static_cast<std::size_t>(c)];
    img.size = n;
    img.value.resize(static_cast<std::size_t>(n * n));
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        img.value[static_cast<std::size_t>(y * n + x)] =
            k[static_cast<std::size_t>((y + 2 * h) * l + x + 2 * h)].real();
  }
  return out;
}

ImageRgb convolveSeparable(const SeparableKernel& kernel, const SignalImage& signal) {
  const int n = signal.size;
  ImageRgb out;
  for (int c = 0; c < kChannels; ++c) {
    auto& img = out[static_cast<std::size_t>(c)];
    img.size = n;
    img.value.assign(static_cast<std::size_t>(n * n), 0.0);
    for (const auto& comp : kernel.components) {
      // Freude eq. 5.10: (E * a_i) * a_i, horizontal then vertical, summed with the signs.
      const auto horizontal = pass(signal.value, n, comp.taps, c, kernel.cellMm, false);
      const auto both = pass(horizontal, n, comp.taps, c, kernel.cellMm, true);
      const double sign = channelOf(comp.sign, c);
      for (std::size_t i = 0; i < both.size(); ++i)
        img.value[i] += sign * both[i];
    }
  }
  return out;
}

std::array<double, kChannels> rmsDifference(const ImageRgb& a, const ImageRgb& b) {
  std::array<double, kChannels> rms{};
  for (std::size_t c = 0; c < kChannels; ++c) {
    double sum = 0;
    for (std::size_t i = 0; i < a[c].value.size(); ++i)
      sum += (a[c].value[i] - b[c].value[i]) * (a[c].value[i] - b[c].value[i]);
    rms[c] = std::sqrt(sum / static_cast<double>(std::max<std::size_t>(1, a[c].value.size())));
  }
  return rms;
}

std::array<double, kChannels> imageSpaceRms(const GroundTruthKernel& truth, const SeparableKernel& kernel,
                                            TestSignal signal, int size) {
  const SignalImage s = makeTestSignal(signal, size);
  return rmsDifference(convolveExact(truth, s), convolveSeparable(kernel, s));
}

}  // namespace tissue::optics
