// metric/simultaneous_reduction.hpp: a common diagonalising basis of two metrics (BOOK.md §1).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/random_metrics.hpp"
#include "metric/simultaneous_reduction.hpp"

using namespace riemesh;
using test_support::random_spd;

namespace {

template <int D>
double rel_err(const SymMat<D>& x, const SymMat<D>& ref) {
  return frobenius(x - ref) / frobenius(ref);
}

/// Checks every claim of the reduction: unit columns, diagonal forms with the given
/// coefficients, dual = basis^{-T}, eigenvectors of A⁻¹B, and the rebuild of both metrics.
template <int D>
void check_reduction(const SymMat<D>& a, const SymMat<D>& b, double tol) {
  const SimultaneousReduction<D> r = simultaneous_reduction(a, b);
  const Mat<D> pt_dual = transpose(r.basis) * r.dual;
  for (int i = 0; i < D; ++i) {
    const Vec<D> ei = r.basis.column(i);
    EXPECT_NEAR(norm(ei), 1.0, 1e-14);
    EXPECT_NEAR(quadratic(a, ei) / r.mu_a[i], 1.0, tol);
    EXPECT_NEAR(quadratic(b, ei) / r.mu_b[i], 1.0, tol);
    // A⁻¹B eᵢ = (mu_b/mu_a) eᵢ  <=>  B eᵢ = ν A eᵢ.
    const Vec<D> res = b * ei - (r.mu_b[i] / r.mu_a[i]) * (a * ei);
    EXPECT_LE(norm(res), tol * norm(b * ei));
    for (int j = 0; j < D; ++j) {
      EXPECT_NEAR(pt_dual(i, j), i == j ? 1.0 : 0.0, tol);
      if (i == j) continue;
      const Vec<D> ej = r.basis.column(j);
      EXPECT_LE(std::abs(bilinear(a, ei, ej)), tol * std::sqrt(r.mu_a[i] * r.mu_a[j]));
      EXPECT_LE(std::abs(bilinear(b, ei, ej)), tol * std::sqrt(r.mu_b[i] * r.mu_b[j]));
    }
  }
  EXPECT_LE(rel_err(rebuild_metric(r, r.mu_a), a), tol);
  EXPECT_LE(rel_err(rebuild_metric(r, r.mu_b), b), tol);
}

}  // namespace

TEST(SimultaneousReduction, DiagonalPairKeepsTheAxes) {
  // A = diag(1, 4), B = diag(9, 1): the axes diagonalise both; mu are the diagonals.
  const SymMat2 a = SymMat2::diagonal(Vec2{{1, 4}}), b = SymMat2::diagonal(Vec2{{9, 1}});
  const SimultaneousReduction<2> r = simultaneous_reduction(a, b);
  for (int i = 0; i < 2; ++i) {
    const int axis = std::abs(r.basis(0, i)) > 0.5 ? 0 : 1;
    EXPECT_NEAR(std::abs(r.basis(axis, i)), 1.0, 1e-15);
    EXPECT_NEAR(r.mu_a[i], a(axis, axis), 1e-14);
    EXPECT_NEAR(r.mu_b[i], b(axis, axis), 1e-14);
  }
  check_reduction(a, b, 1e-14);
}

TEST(SimultaneousReduction, RepeatedEigenvaluesGiveAnAOrthogonalBasis) {
  // B = 3A: every vector is an eigenvector of A⁻¹B = 3I; the basis must still be A-orthogonal.
  const SymMat3 a{{2.0, 0.5, 1.0, 0.1, -0.2, 3.0}};
  check_reduction(a, 3.0 * a, 1e-13);
  const SimultaneousReduction<3> r = simultaneous_reduction(a, 3.0 * a);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(r.mu_b[i] / r.mu_a[i], 3.0, 1e-13);
  // Identical metrics: ν = 1.
  const Vec3 nu = relative_eigenvalues(a, a);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(nu[i], 1.0, 1e-14);
}

TEST(SimultaneousReduction, RelativeEigenvaluesOfAScaledRotatedPair) {
  // B = R diag(2, 8) Rᵀ against A = I: ν = (2, 8) ascending.
  const double c = std::cos(0.7), s = std::sin(0.7);
  const SymMat2 b = compose(Mat2{{{c, -s}, {s, c}}}, Vec2{{8, 2}});
  const Vec2 nu = relative_eigenvalues(SymMat2::identity(), b);
  EXPECT_NEAR(nu[0], 2.0, 1e-14);
  EXPECT_NEAR(nu[1], 8.0, 1e-14);
}

template <int D>
void random_pairs(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  for (int k = 0; k < 500; ++k) {
    const SymMat<D> a = random_spd<D>(rng, 1e3), b = random_spd<D>(rng, 1e3);
    // Tolerance: the eigenproblem of A^{-1/2}BA^{-1/2} is conditioned by both anisotropies
    // (1e3 in eigenvalues each) and the scale ratio.
    check_reduction(a, b, 1e-9);
  }
}
TEST(SimultaneousReduction, RandomPairs2D) { random_pairs<2>(11); }
TEST(SimultaneousReduction, RandomPairs3D) { random_pairs<3>(12); }
