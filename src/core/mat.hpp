#pragma once
// Small dense square matrices Mat<D> (row-major a[i][j]), for non-orthogonal bases such as the
// simultaneous-reduction basis P or a Cholesky factor L. Symmetric tensors live in SymMat<D>.
#include <cmath>

#include "core/vec.hpp"

namespace riemesh {

template <int D>
struct Mat {
  double a[D][D];

  constexpr double& operator()(int i, int j) { return a[i][j]; }
  constexpr const double& operator()(int i, int j) const { return a[i][j]; }

  static constexpr Mat identity() {
    Mat m{};
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j) m.a[i][j] = (i == j) ? 1.0 : 0.0;
    return m;
  }
  /// The matrix whose columns are the given vectors.
  static constexpr Mat from_columns(const Vec<D> (&cols)[D]) {
    Mat m{};
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j) m.a[i][j] = cols[j][i];
    return m;
  }
  constexpr Vec<D> column(int j) const {
    Vec<D> v{};
    for (int i = 0; i < D; ++i) v[i] = a[i][j];
    return v;
  }
  constexpr void set_column(int j, const Vec<D>& v) {
    for (int i = 0; i < D; ++i) a[i][j] = v[i];
  }
  friend constexpr bool operator==(const Mat&, const Mat&) = default;
};

using Mat2 = Mat<2>;
using Mat3 = Mat<3>;

template <int D>
constexpr Mat<D> transpose(const Mat<D>& m) {
  Mat<D> t{};
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) t(i, j) = m(j, i);
  return t;
}
template <int D>
constexpr Mat<D> operator*(const Mat<D>& x, const Mat<D>& y) {
  Mat<D> r{};
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) {
      double s = 0.0;
      for (int k = 0; k < D; ++k) s += x(i, k) * y(k, j);
      r(i, j) = s;
    }
  return r;
}
template <int D>
constexpr Vec<D> operator*(const Mat<D>& m, const Vec<D>& v) {
  Vec<D> r{};
  for (int i = 0; i < D; ++i) {
    double s = 0.0;
    for (int k = 0; k < D; ++k) s += m(i, k) * v[k];
    r[i] = s;
  }
  return r;
}
template <int D>
constexpr Mat<D> operator+(const Mat<D>& x, const Mat<D>& y) {
  Mat<D> r{};
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) r(i, j) = x(i, j) + y(i, j);
  return r;
}
template <int D>
constexpr Mat<D> operator*(double s, const Mat<D>& x) {
  Mat<D> r{};
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) r(i, j) = s * x(i, j);
  return r;
}

constexpr double det(const Mat2& m) { return m(0, 0) * m(1, 1) - m(0, 1) * m(1, 0); }
constexpr double det(const Mat3& m) {
  return m(0, 0) * (m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1)) -
         m(0, 1) * (m(1, 0) * m(2, 2) - m(1, 2) * m(2, 0)) +
         m(0, 2) * (m(1, 0) * m(2, 1) - m(1, 1) * m(2, 0));
}

/// Inverse by the adjugate; the caller guarantees det != 0 (check det first where it may vanish).
constexpr Mat2 inverse(const Mat2& m) {
  const double id = 1.0 / det(m);
  return {{{m(1, 1) * id, -m(0, 1) * id}, {-m(1, 0) * id, m(0, 0) * id}}};
}
constexpr Mat3 inverse(const Mat3& m) {
  Mat3 c{};
  c(0, 0) = m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1);
  c(0, 1) = m(0, 2) * m(2, 1) - m(0, 1) * m(2, 2);
  c(0, 2) = m(0, 1) * m(1, 2) - m(0, 2) * m(1, 1);
  c(1, 0) = m(1, 2) * m(2, 0) - m(1, 0) * m(2, 2);
  c(1, 1) = m(0, 0) * m(2, 2) - m(0, 2) * m(2, 0);
  c(1, 2) = m(0, 2) * m(1, 0) - m(0, 0) * m(1, 2);
  c(2, 0) = m(1, 0) * m(2, 1) - m(1, 1) * m(2, 0);
  c(2, 1) = m(0, 1) * m(2, 0) - m(0, 0) * m(2, 1);
  c(2, 2) = m(0, 0) * m(1, 1) - m(0, 1) * m(1, 0);
  const double id = 1.0 / (m(0, 0) * c(0, 0) + m(0, 1) * c(1, 0) + m(0, 2) * c(2, 0));
  return id * c;
}

/// The matrix with the vectors of a simplex's edges from its first vertex as columns.
template <int D>
constexpr Mat<D> edge_matrix(const Vec<D> (&p)[D + 1]) {
  Mat<D> m{};
  for (int j = 0; j < D; ++j) m.set_column(j, p[j + 1] - p[0]);
  return m;
}

}  // namespace riemesh
