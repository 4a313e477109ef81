#pragma once
// Random test inputs with fixed seeds: rotations and SPD tensors of given anisotropy.
#include <cmath>
#include <random>

#include "core/eigen.hpp"
#include "core/mat.hpp"
#include "core/symmat.hpp"

namespace riemesh::test_support {

/// A uniformly random rotation (columns orthonormal, det +1), by Gram-Schmidt on Gaussian columns.
template <int D>
Mat<D> random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> n01;
  Mat<D> r{};
  for (int j = 0; j < D; ++j) {
    Vec<D> v{};
    for (int i = 0; i < D; ++i) v[i] = n01(rng);
    for (int pass = 0; pass < 2; ++pass)  // Gram-Schmidt twice: orthogonal to rounding level
      for (int k = 0; k < j; ++k) v -= dot(v, r.column(k)) * r.column(k);
    r.set_column(j, normalize(v));
  }
  if (det(r) < 0) r.set_column(0, -r.column(0));
  return r;
}

/// Eigenvalues log-uniform in [1, ratio] times a log-uniform scale in [1e-3, 1e3].
template <int D>
Vec<D> random_spectrum(std::mt19937_64& rng, double ratio) {
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  const double scale = std::pow(10.0, -3.0 + 6.0 * u01(rng));
  Vec<D> l{};
  for (int i = 0; i < D; ++i) l[i] = scale * std::pow(ratio, u01(rng));
  return l;
}

/// A random SPD tensor with eigenvalue ratio up to `ratio`.
template <int D>
SymMat<D> random_spd(std::mt19937_64& rng, double ratio = 1e3) {
  return compose(random_rotation<D>(rng), random_spectrum<D>(rng, ratio));
}

}  // namespace riemesh::test_support
