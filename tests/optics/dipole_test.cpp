// Dipole and multipole against shared/reference/dipole.md and against their own integrals.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

#include "tissue/optics/dipole.h"
#include "tissue/optics/multipole.h"

namespace tissue::optics {
namespace {

// Integral of f(r) 2 pi r dr over [0, rMax] by composite Simpson's rule.
double integratePlane(const std::function<double(double)>& f, double rMax, int intervals = 200000) {
  const double h = rMax / intervals;
  double sum = 0;
  for (int i = 0; i <= intervals; ++i) {
    const double r = i * h;
    const double w = (i == 0 || i == intervals) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    sum += w * f(r) * 2.0 * std::numbers::pi * r;
  }
  return sum * h / 3.0;
}

// Reference value from dipole.md: relative agreement to the digits given.
void expectRel(double value, double reference, double rel = 2e-5) {
  EXPECT_NEAR(value, reference, rel * std::abs(reference));
}

TEST(Dipole, BoundaryTermAMatchesTheReferenceTable) {
  const double etas[] = {1.0, 1.3, 1.33, 1.4, 1.5};
  const double as[] = {1.003205, 2.602064, 2.790444, 3.250697, 3.959497};
  for (int i = 0; i < 5; ++i)
    expectRel(makeDipole(0.1, 1.0, etas[i]).a, as[i], 1e-6);
}

TEST(Dipole, Skin1RegressionValues) {
  // Skin1 (Jensen 2001): sigma_s' = (0.74, 0.88, 1.01), sigma_a = (0.032, 0.17, 0.48) mm^-1, eta 1.3.
  const Dipole red = makeDipole(0.032, 0.74, 1.3);
  expectRel(red.alphaPrime, 0.958549);
  expectRel(red.sigmaTr, 0.272235);
  expectRel(red.zr, 1.295337);
  expectRel(red.zv, 5.789403);
  expectRel(dipoleTotalRd(red), 0.435956);
  const double radii[] = {0, 0.5, 1, 2, 4, 8};
  const double values[] = {0.0444311, 0.0360482, 0.022019, 0.00726136, 0.00145169, 0.000180543};
  for (int i = 0; i < 6; ++i)
    expectRel(dipoleRd(red, radii[i]), values[i]);
  const Dipole green = makeDipole(0.17, 0.88, 1.3);
  expectRel(dipoleTotalRd(green), 0.227331);
  expectRel(dipoleRd(green, 0), 0.0628239);
  expectRel(dipoleRd(green, 1), 0.0182336);
  expectRel(dipoleRd(green, 4), 0.00028533);
  const Dipole blue = makeDipole(0.48, 1.01, 1.3);
  expectRel(dipoleTotalRd(blue), 0.130999);
  expectRel(dipoleRd(blue, 0), 0.0892566);
  expectRel(dipoleRd(blue, 1), 0.0100962);
  expectRel(dipoleRd(blue, 4), 1.7012e-05, 1e-4);
}

TEST(Dipole, MarbleRegressionValues) {
  const double sps[] = {2.19, 2.62, 3.00}, sa[] = {0.0021, 0.0041, 0.0071};
  const double totals[] = {0.830191, 0.790960, 0.752610}, at1mm[] = {0.0348467, 0.03433, 0.0336751};
  for (int c = 0; c < 3; ++c) {
    const Dipole d = makeDipole(sa[c], sps[c], 1.5);
    expectRel(dipoleTotalRd(d), totals[c]);
    expectRel(dipoleRd(d, 1.0), at1mm[c], 1e-4);
  }
}

TEST(Dipole, ClosedFormTotalEqualsTheIntegralOfTheProfile) {
  const double sps[] = {0.74, 0.88, 1.01, 2.19}, sa[] = {0.032, 0.17, 0.48, 0.0021},
               eta[] = {1.3, 1.3, 1.3, 1.5};
  for (int c = 0; c < 4; ++c) {
    const Dipole d = makeDipole(sa[c], sps[c], eta[c]);
    const double rMax = 40.0 / d.sigmaTr + 100.0 * d.zv;  // the tail beyond is below 1e-12
    const double numeric = integratePlane([&](double r) { return dipoleRd(d, r); }, rMax, 2000000);
    std::printf("  dipole total %.7f, integral of R_d(r) 2 pi r dr %.7f\n", dipoleTotalRd(d), numeric);
    EXPECT_NEAR(numeric, dipoleTotalRd(d), 1e-6);
  }
}

TEST(Multipole, ThickSlabReducesToTheDipole) {
  const Multipole m = makeMultipole(0.032, 0.74, 1.3, 500.0);
  const Dipole d = makeDipole(0.032, 0.74, 1.3);
  for (double r : {0.0, 0.5, 2.0, 8.0})
    expectRel(multipoleR(m, r), dipoleRd(d, r), 1e-9);
  expectRel(multipoleTotalR(m), dipoleTotalRd(d), 1e-9);
  EXPECT_LT(multipoleTotalT(m), 1e-12);
}

TEST(Multipole, ClosedFormTotalsEqualTheIntegralsAndThinSlabsTransmit) {
  // Thickness above the source depth l = 1/sigma_t' = 0.95 mm: below it the real source lies
  // outside the slab and T turns negative (multipole.h).
  for (double thickness : {1.5, 3.0, 10.0}) {
    const Multipole m = makeMultipole(0.17, 0.88, 1.3, thickness);
    const double rMax = 40.0 / m.dipole.sigmaTr + 200.0 * m.dipole.zv;
    const double r = integratePlane([&](double x) { return multipoleR(m, x); }, rMax, 2000000);
    const double t = integratePlane([&](double x) { return multipoleT(m, x); }, rMax, 2000000);
    std::printf("  slab %.1f mm: R %.6f (integral %.6f), T %.6f (integral %.6f)\n", thickness,
                multipoleTotalR(m), r, multipoleTotalT(m), t);
    EXPECT_NEAR(r, multipoleTotalR(m), 1e-6);
    EXPECT_NEAR(t, multipoleTotalT(m), 1e-6);
    EXPECT_GT(multipoleTotalT(m), 0.0);
    EXPECT_LT(multipoleTotalR(m) + multipoleTotalT(m), 1.0);
  }
  // Thinner slabs reflect less and transmit more.
  EXPECT_LT(multipoleTotalR(makeMultipole(0.17, 0.88, 1.3, 1.5)),
            multipoleTotalR(makeMultipole(0.17, 0.88, 1.3, 3)));
  EXPECT_GT(multipoleTotalT(makeMultipole(0.17, 0.88, 1.3, 1.5)),
            multipoleTotalT(makeMultipole(0.17, 0.88, 1.3, 3)));
}

}  // namespace
}  // namespace tissue::optics
