#pragma once
// Printing a metric for people (sizes, directions, anisotropy, determinant) or as one JSON object.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "metric/metric.hpp"

namespace riemesh::cli {

/// What `riemesh metric calc` prints about a resulting metric.
template <int D>
struct MetricSummary {
  SymMat<D> metric;
  Vec<D> sizes;      // descending
  Mat<D> directions;  // unit directions of the sizes, as columns
  double anisotropy;
  double det;
};

/// Computed on m over its largest coefficient c (the eigen solver overflowed on entries of
/// 1e160: NaN directions), sizes and determinant scaled back.
template <int D>
MetricSummary<D> summarize(const SymMat<D>& m) {
  double c = 0.0;
  for (const double x : m.c) c = std::max(c, std::abs(x));
  if (!(c > 0.0) || !std::isfinite(c)) c = 1.0;
  const MetricSizes<D> s = sizes((1.0 / c) * m);
  MetricSummary<D> out{m, s.sizes, s.directions, s.sizes[0] / s.sizes[D - 1], 0.0};
  double det = 1.0;
  for (int i = 0; i < D; ++i) {
    out.sizes[i] = s.sizes[i] / std::sqrt(c);
    det *= c / (s.sizes[i] * s.sizes[i]);  // each factor in range: λ_i of m
  }
  out.det = det;
  return out;
}

/// The JSON object {"metric": [...], "sizes": [...], "directions": [...], "anisotropy": a,
/// "det": d}; 2D directions are angles in degrees in (-90, 90], 3D directions unit vectors.
template <int D>
std::string to_json(const MetricSummary<D>& s);

/// A few aligned lines for a terminal.
template <int D>
std::string to_text(const MetricSummary<D>& s);

}  // namespace riemesh::cli
