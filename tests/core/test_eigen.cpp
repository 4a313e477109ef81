// Eigendecomposition of symmetric 2x2 and 3x3 tensors: exact cases, backward stability for
// eigenvalue spreads up to 1e12 and beyond, repeated eigenvalues, orthonormality.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "core/eigen.hpp"
#include "core/random_metrics.hpp"

using namespace riemesh;
using riemesh::test_support::random_rotation;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

template <int D>
double reconstruction_error(const SymMat<D>& m, const SymEigen<D>& e) {
  return frobenius(compose(e.vectors, e.values) - m) / frobenius(m);
}

template <int D>
double orthogonality_error(const Mat<D>& r) {
  const Mat<D> rtr = transpose(r) * r;
  double err = 0.0;
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) err = std::max(err, std::abs(rtr(i, j) - (i == j ? 1.0 : 0.0)));
  return err;
}

}  // namespace

TEST(Eigen, DiagonalIsExactAndSorted) {
  const SymEigen<3> e = eigen(SymMat3{{3.0, 0.0, 1e-12, 0.0, 0.0, 2.0}});
  EXPECT_EQ(e.values[0], 1e-12);
  EXPECT_EQ(e.values[1], 2.0);
  EXPECT_EQ(e.values[2], 3.0);
  EXPECT_EQ(std::abs(e.vectors(1, 0)), 1.0);  // eigenvector of 1e-12 is e_y
  const SymEigen<2> e2 = eigen(SymMat2{{5.0, 0.0, -1.0}});
  EXPECT_EQ(e2.values[0], -1.0);
  EXPECT_EQ(e2.values[1], 5.0);
}

TEST(Eigen, TwoByTwoAnalytic) {
  // [[2,1],[1,2]]: eigenvalues 1 and 3, eigenvectors (1,-1)/√2 and (1,1)/√2.
  const SymEigen<2> e = eigen(SymMat2{{2.0, 1.0, 2.0}});
  EXPECT_NEAR(e.values[0], 1.0, 4 * kEps);
  EXPECT_NEAR(e.values[1], 3.0, 4 * kEps);
  EXPECT_NEAR(std::abs(e.vectors(0, 1)), std::sqrt(0.5), 4 * kEps);
  EXPECT_NEAR(e.vectors(0, 1) * e.vectors(1, 1), 0.5, 4 * kEps);  // same sign: (1,1)
}

TEST(Eigen, ThreeByThreeAnalytic) {
  // [[2,-1,0],[-1,2,-1],[0,-1,2]] (1D Laplacian): eigenvalues 2-√2, 2, 2+√2.
  const SymEigen<3> e = eigen(SymMat3{{2.0, -1.0, 2.0, 0.0, -1.0, 2.0}});
  EXPECT_NEAR(e.values[0], 2.0 - std::sqrt(2.0), 8 * kEps);
  EXPECT_NEAR(e.values[1], 2.0, 8 * kEps);
  EXPECT_NEAR(e.values[2], 2.0 + std::sqrt(2.0), 8 * kEps);
  // Eigenvector of 2 is (1, 0, -1)/√2.
  EXPECT_NEAR(std::abs(e.vectors(0, 1)), std::sqrt(0.5), 8 * kEps);
  EXPECT_NEAR(std::abs(e.vectors(1, 1)), 0.0, 8 * kEps);
}

template <int D>
void check_random_spectra(double ratio, int samples) {
  std::mt19937_64 rng(42 + D);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  double worst_rec = 0, worst_orth = 0, worst_val = 0;
  for (int s = 0; s < samples; ++s) {
    const Mat<D> r = random_rotation<D>(rng);
    Vec<D> l{};
    for (int i = 0; i < D; ++i) l[i] = std::pow(ratio, u01(rng));  // spread up to `ratio`
    l[0] = 1.0;
    l[D - 1] = ratio;
    const SymMat<D> m = compose(r, l);
    const SymEigen<D> e = eigen(m);
    worst_rec = std::max(worst_rec, reconstruction_error(m, e));
    worst_orth = std::max(worst_orth, orthogonality_error(e.vectors));
    std::sort(l.x, l.x + D);
    for (int i = 0; i < D; ++i) {
      // Backward stability bounds eigenvalue errors by c·ε·λ_max (Weyl); the input itself is
      // only known to that accuracy once rounded to doubles.
      worst_val = std::max(worst_val, std::abs(e.values[i] - l[i]) / ratio);
      ASSERT_GT(e.values[i], 0.0) << "SPD input must give positive eigenvalues";
      if (i > 0) {
        ASSERT_LE(e.values[i - 1], e.values[i]);
      }
    }
  }
  EXPECT_LT(worst_rec, 50 * kEps) << "ratio " << ratio;
  EXPECT_LT(worst_orth, 50 * kEps) << "ratio " << ratio;
  EXPECT_LT(worst_val, 50 * kEps) << "ratio " << ratio;
}

TEST(Eigen, BackwardStableUpToRatio1e12_2D) {
  for (double ratio : {1.0 + 1e-9, 10.0, 1e4, 1e8, 1e12}) check_random_spectra<2>(ratio, 2000);
}
TEST(Eigen, BackwardStableUpToRatio1e12_3D) {
  for (double ratio : {1.0 + 1e-9, 10.0, 1e4, 1e8, 1e12}) check_random_spectra<3>(ratio, 2000);
}

TEST(Eigen, SmallEigenvalueRelativeAccuracyWhenWellDetermined) {
  // A tensor rotated about z only: the z eigenvalue (1e-12) is decoupled, so the method must
  // return it to full relative accuracy even though it is 1e12 times smaller than the largest.
  const double c = std::cos(0.3), s = std::sin(0.3);
  const Mat3 r{{{c, -s, 0}, {s, c, 0}, {0, 0, 1}}};
  const SymMat3 m = compose(r, Vec3{{1.0, 1e-6, 1e-12}});
  const SymEigen<3> e = eigen(m);
  EXPECT_NEAR(e.values[0] / 1e-12, 1.0, 1e-12);
  EXPECT_NEAR(e.values[1] / 1e-6, 1.0, 1e-9);
  EXPECT_NEAR(e.values[2], 1.0, 1e-15);
}

TEST(Eigen, RepeatedEigenvalues3D) {
  std::mt19937_64 rng(7);
  for (int s = 0; s < 500; ++s) {
    const Mat3 r = random_rotation<3>(rng);
    for (const Vec3& l : {Vec3{{2, 2, 5}}, Vec3{{1, 7, 7}}, Vec3{{3, 3, 3}}, Vec3{{1e-8, 1e-8, 1}},
                          Vec3{{1, 1 + 1e-13, 1 + 2e-13}}}) {
      const SymMat3 m = compose(r, l);
      const SymEigen<3> e = eigen(m);
      EXPECT_LT(reconstruction_error(m, e), 50 * kEps);
      EXPECT_LT(orthogonality_error(e.vectors), 50 * kEps);
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(e.values[i], l[i], 50 * kEps * l[2]);
    }
  }
}

TEST(Eigen, IndefiniteAndScaledInputs) {
  // Matrix logarithms are indefinite; scaling must not overflow or underflow.
  std::mt19937_64 rng(11);
  for (double scale : {1e-200, 1e-30, 1.0, 1e30, 1e200}) {
    const Mat3 r = random_rotation<3>(rng);
    const Vec3 l{{-3.0 * scale, 0.5 * scale, 2.0 * scale}};
    const SymMat3 m = compose(r, l);
    SymEigen<3> e = eigen(m);
    // Compare at unit scale (squares of 1e-200 underflow in the error measure itself).
    e.values = e.values / scale;
    EXPECT_LT(reconstruction_error(compose(r, l / scale), e), 50 * kEps) << scale;
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(e.values[i], l[i] / scale, 50 * kEps * 3);
  }
}

TEST(Eigen, TwoByTwoScaledInputs) {
  // As the 3D case above: the Jacobi rotation's h² + b² overflowed beyond 1e150 and underflowed
  // below 1e-150 (t = b/0 = inf, NaN eigenvalues).
  std::mt19937_64 rng(12);
  for (double scale : {1e-300, 1e-200, 1e-160, 1e-30, 1.0, 1e30, 1e160, 1e200, 1e300}) {
    const Mat2 r = random_rotation<2>(rng);
    const Vec2 l{{-3.0 * scale, 0.5 * scale}};
    SymEigen<2> e = eigen(compose(r, l));
    e.values = e.values / scale;
    EXPECT_LT(reconstruction_error(compose(r, l / scale), e), 50 * kEps) << scale;
    for (int i = 0; i < 2; ++i) EXPECT_NEAR(e.values[i], l[i] / scale, 50 * kEps * 3) << scale;
    EXPECT_LT(orthogonality_error(e.vectors), 4 * kEps) << scale;
  }
}

TEST(Eigen, TwoByTwoTinyOffDiagonal) {
  // The identity plus an off-diagonal 1e-170 or 1e-310 (a metric read from a file): eigenvalues
  // 1 ± b, i.e. 1, and orthonormal vectors. It gave NaN, and the metric was "not positive
  // definite" (QA hunt 5 F15).
  for (const double b : {1e-170, -1e-170, 1e-310}) {
    const SymEigen<2> e = eigen(SymMat2{{1.0, b, 1.0}});
    EXPECT_EQ(e.values[0], 1.0) << b;
    EXPECT_EQ(e.values[1], 1.0) << b;
    EXPECT_LT(orthogonality_error(e.vectors), 4 * kEps) << b;
  }
}

TEST(Eigen, ZeroMatrix) {
  const SymEigen<3> e = eigen(SymMat3::zero());
  for (int i = 0; i < 3; ++i) EXPECT_EQ(e.values[i], 0.0);
  EXPECT_EQ(orthogonality_error(e.vectors), 0.0);
}
