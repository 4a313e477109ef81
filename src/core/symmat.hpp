#pragma once
// Symmetric D x D tensors stored packed: SymMat<D>.
//
// Component order (the one order used everywhere inside Riemesh, and also the order of Medit
// .sol files, so io/ copies coefficients as they are):
//   2D: m11 m12 m22                    -> c[0] c[1] c[2]
//   3D: m11 m12 m22 m13 m23 m33        -> c[0] .. c[5]
// i.e. the upper triangle column by column: (i, j), i <= j, lives at j*(j+1)/2 + i.
// MMG's internal order (m11 m12 m13 m22 m23 m33) differs: never assume it here.
#include <cmath>

#include "core/mat.hpp"
#include "core/vec.hpp"

namespace riemesh {

/// Index of entry (i, j) in the packed storage (any order of i and j).
constexpr int sym_index(int i, int j) {
  return (i <= j) ? j * (j + 1) / 2 + i : i * (i + 1) / 2 + j;
}

template <int D>
struct SymMat {
  static constexpr int kSize = D * (D + 1) / 2;
  double c[kSize];

  constexpr double operator()(int i, int j) const { return c[sym_index(i, j)]; }
  constexpr double& at(int i, int j) { return c[sym_index(i, j)]; }

  static constexpr SymMat zero() {
    SymMat m{};
    for (int k = 0; k < kSize; ++k) m.c[k] = 0.0;
    return m;
  }
  static constexpr SymMat identity() { return diagonal(1.0); }
  /// s * I.
  static constexpr SymMat diagonal(double s) {
    SymMat m = zero();
    for (int i = 0; i < D; ++i) m.at(i, i) = s;
    return m;
  }
  static constexpr SymMat diagonal(const Vec<D>& d) {
    SymMat m = zero();
    for (int i = 0; i < D; ++i) m.at(i, i) = d[i];
    return m;
  }
  /// The symmetric part (A + Aᵀ)/2 of a dense matrix.
  static constexpr SymMat from_mat(const Mat<D>& a) {
    SymMat m{};
    for (int j = 0; j < D; ++j)
      for (int i = 0; i <= j; ++i) m.at(i, j) = 0.5 * (a(i, j) + a(j, i));
    return m;
  }
  constexpr Mat<D> to_mat() const {
    Mat<D> a{};
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j) a(i, j) = (*this)(i, j);
    return a;
  }
  friend constexpr bool operator==(const SymMat&, const SymMat&) = default;
};

using SymMat2 = SymMat<2>;
using SymMat3 = SymMat<3>;

template <int D>
constexpr SymMat<D> operator+(const SymMat<D>& a, const SymMat<D>& b) {
  SymMat<D> r{};
  for (int k = 0; k < SymMat<D>::kSize; ++k) r.c[k] = a.c[k] + b.c[k];
  return r;
}
template <int D>
constexpr SymMat<D> operator-(const SymMat<D>& a, const SymMat<D>& b) {
  SymMat<D> r{};
  for (int k = 0; k < SymMat<D>::kSize; ++k) r.c[k] = a.c[k] - b.c[k];
  return r;
}
template <int D>
constexpr SymMat<D> operator*(double s, const SymMat<D>& a) {
  SymMat<D> r{};
  for (int k = 0; k < SymMat<D>::kSize; ++k) r.c[k] = s * a.c[k];
  return r;
}
template <int D>
constexpr SymMat<D>& operator+=(SymMat<D>& a, const SymMat<D>& b) {
  for (int k = 0; k < SymMat<D>::kSize; ++k) a.c[k] += b.c[k];
  return a;
}

/// M v.
template <int D>
constexpr Vec<D> operator*(const SymMat<D>& m, const Vec<D>& v) {
  Vec<D> r{};
  for (int i = 0; i < D; ++i) {
    double s = 0.0;
    for (int k = 0; k < D; ++k) s += m(i, k) * v[k];
    r[i] = s;
  }
  return r;
}

/// uᵀ M v.
template <int D>
constexpr double bilinear(const SymMat<D>& m, const Vec<D>& u, const Vec<D>& v) {
  return dot(u, m * v);
}
/// uᵀ M u (the squared length of u in M).
template <int D>
constexpr double quadratic(const SymMat<D>& m, const Vec<D>& u) {
  return dot(u, m * u);
}

template <int D>
constexpr double trace(const SymMat<D>& m) {
  double s = 0.0;
  for (int i = 0; i < D; ++i) s += m(i, i);
  return s;
}

/// Frobenius norm.
template <int D>
inline double frobenius(const SymMat<D>& m) {
  double s = 0.0;
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) s += m(i, j) * m(i, j);
  return std::sqrt(s);
}

constexpr double det(const SymMat2& m) { return m.c[0] * m.c[2] - m.c[1] * m.c[1]; }
constexpr double det(const SymMat3& m) {
  // m11 (m22 m33 - m23²) - m12 (m12 m33 - m23 m13) + m13 (m12 m23 - m22 m13)
  return m.c[0] * (m.c[2] * m.c[5] - m.c[4] * m.c[4]) -
         m.c[1] * (m.c[1] * m.c[5] - m.c[4] * m.c[3]) +
         m.c[3] * (m.c[1] * m.c[4] - m.c[2] * m.c[3]);
}

/// Inverse by the adjugate (the caller guarantees a non-singular matrix).
constexpr SymMat2 inverse(const SymMat2& m) {
  const double id = 1.0 / det(m);
  return {{m.c[2] * id, -m.c[1] * id, m.c[0] * id}};
}
constexpr SymMat3 inverse(const SymMat3& m) {
  const double a11 = m.c[2] * m.c[5] - m.c[4] * m.c[4];
  const double a12 = m.c[3] * m.c[4] - m.c[1] * m.c[5];
  const double a22 = m.c[0] * m.c[5] - m.c[3] * m.c[3];
  const double a13 = m.c[1] * m.c[4] - m.c[2] * m.c[3];
  const double a23 = m.c[1] * m.c[3] - m.c[0] * m.c[4];
  const double a33 = m.c[0] * m.c[2] - m.c[1] * m.c[1];
  const double id = 1.0 / (m.c[0] * a11 + m.c[1] * a12 + m.c[3] * a13);
  return {{a11 * id, a12 * id, a22 * id, a13 * id, a23 * id, a33 * id}};
}

/// P S Pᵀ for a dense P and symmetric S (a change of basis of a quadratic form).
template <int D>
constexpr SymMat<D> congruence(const Mat<D>& p, const SymMat<D>& s) {
  SymMat<D> r{};
  for (int j = 0; j < D; ++j)
    for (int i = 0; i <= j; ++i) {
      double sum = 0.0;
      for (int k = 0; k < D; ++k)
        for (int l = 0; l < D; ++l) sum += p(i, k) * s(k, l) * p(j, l);
      r.at(i, j) = sum;
    }
  return r;
}

/// P diag(d) Pᵀ: the symmetric matrix with columns of P as eigenvectors and d as eigenvalues
/// (when P is orthogonal), or the quadratic form whose dual basis is P (when it is not).
template <int D>
constexpr SymMat<D> congruence_diag(const Mat<D>& p, const Vec<D>& d) {
  SymMat<D> r{};
  for (int j = 0; j < D; ++j)
    for (int i = 0; i <= j; ++i) {
      double sum = 0.0;
      for (int k = 0; k < D; ++k) sum += p(i, k) * d[k] * p(j, k);
      r.at(i, j) = sum;
    }
  return r;
}

/// u uᵀ.
template <int D>
constexpr SymMat<D> outer(const Vec<D>& u) {
  SymMat<D> r{};
  for (int j = 0; j < D; ++j)
    for (int i = 0; i <= j; ++i) r.at(i, j) = u[i] * u[j];
  return r;
}

template <int D>
inline bool is_finite(const SymMat<D>& m) {
  for (int k = 0; k < SymMat<D>::kSize; ++k)
    if (!std::isfinite(m.c[k])) return false;
  return true;
}

/// Whether m has no off-diagonal term (isotropic or axis-aligned, for a metric).
template <int D>
constexpr bool is_diagonal(const SymMat<D>& m) {
  for (int i = 0; i < D; ++i)
    for (int j = i + 1; j < D; ++j)
      if (m(i, j) != 0.0) return false;
  return true;
}

}  // namespace riemesh
