#pragma once
/// \file
/// Error measures of separable kernels against their ground truth (Freude §5.1, §6.2): RMS in
/// kernel space, and RMS in image space of test signals convolved with the taps (two 1D passes,
/// linear interpolation, clamp to edge, as a shader does) against the exact 2D convolution with
/// the ground-truth grid (by FFT). Images have one pixel per grid cell (cellMm).

#include <array>
#include <vector>

#include "tissue/optics/ground_truth_kernel.h"
#include "tissue/optics/kernel.h"

namespace tissue::optics {

/// A square single-channel image, row-major, values in [0, 1] for the test signals.
struct SignalImage {
  int size = 0;               ///< pixels per side
  std::vector<double> value;  ///< size * size
};

/// An RGB image, one SignalImage per channel.
using ImageRgb = std::array<SignalImage, kChannels>;

/// The test signals (Freude §6.2 and §5.3).
enum class TestSignal {
  VerticalEdge,        ///< white left half, black right half (Freude Fig. 6.3-6.5)
  CircleAndSquares,    ///< a disc and two tilted, adjacent squares (Freude Fig. 6.6-6.10)
  ShadedPatch,         ///< a Lambert-lit bumpy patch with a cast shadow (Freude Fig. 5.10)
  AdditivelySeparable  ///< E1(x) + E2(y), eq. 5.14 (pre-integration is exact for it)
};

/// The signal `signal` at `size` x `size` pixels.
SignalImage makeTestSignal(TestSignal signal, int size = 256);

/// Kernel-space RMS per channel over the (2h+1)^2 grid: sqrt(mean (R_d - sum_i sign_i a_i a_i^T)^2)
/// with the components' dense forms (Freude Table 6.3, before its per-table normalisation).
std::array<double, kChannels> kernelSpaceRms(const GroundTruthKernel& truth, const SeparableKernel& kernel);

/// The exact 2D convolution of `signal` with each channel of `truth` (clamp to edge), by FFT.
ImageRgb convolveExact(const GroundTruthKernel& truth, const SignalImage& signal);

/// The two-pass separable convolution of `signal` with the kernel's taps, summed over components.
ImageRgb convolveSeparable(const SeparableKernel& kernel, const SignalImage& signal);

/// RMS of the per-channel difference of two images of the same size.
std::array<double, kChannels> rmsDifference(const ImageRgb& a, const ImageRgb& b);

/// Image-space RMS of `kernel` on `signal` against the exact convolution with `truth`.
std::array<double, kChannels> imageSpaceRms(const GroundTruthKernel& truth, const SeparableKernel& kernel,
                                            TestSignal signal, int size = 256);

}  // namespace tissue::optics
