#pragma once
// Small dense linear systems (least-squares normal equations of local fits).
#include <algorithm>
#include <cmath>
#include <utility>

namespace riemesh {

/// Solves the leading n x n block of a c = r in place (c returned in r) by Gaussian elimination
/// with partial pivoting; false when a pivot is below 1e-10 of the largest diagonal entry (a
/// rank-deficient fit), a and r then hold partial results.
template <int N>
bool solve_dense(double (&a)[N][N], double (&r)[N], int n = N) {
  double scale = 0.0;
  for (int i = 0; i < n; ++i) scale = std::max(scale, std::abs(a[i][i]));
  if (!(scale > 0.0)) return false;
  for (int k = 0; k < n; ++k) {
    int piv = k;
    for (int i = k + 1; i < n; ++i)
      if (std::abs(a[i][k]) > std::abs(a[piv][k])) piv = i;
    if (!(std::abs(a[piv][k]) > 1e-10 * scale)) return false;
    std::swap(a[k], a[piv]);
    std::swap(r[k], r[piv]);
    for (int i = k + 1; i < n; ++i) {
      const double f = a[i][k] / a[k][k];
      for (int j = k; j < n; ++j) a[i][j] -= f * a[k][j];
      r[i] -= f * r[k];
    }
  }
  for (int k = n - 1; k >= 0; --k) {
    double s = r[k];
    for (int j = k + 1; j < n; ++j) s -= a[k][j] * r[j];
    r[k] = s / a[k][k];
  }
  return true;
}

}  // namespace riemesh
