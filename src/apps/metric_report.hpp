#pragma once
// Printing a metric for people (sizes, directions, anisotropy, determinant) or as one JSON object.
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

template <int D>
MetricSummary<D> summarize(const SymMat<D>& m) {
  const MetricSizes<D> s = sizes(m);
  return {m, s.sizes, s.directions, s.sizes[0] / s.sizes[D - 1], riemesh::det(m)};
}

/// The JSON object {"metric": [...], "sizes": [...], "directions": [...], "anisotropy": a,
/// "det": d}; 2D directions are angles in degrees in (-90, 90], 3D directions unit vectors.
template <int D>
std::string to_json(const MetricSummary<D>& s);

/// A few aligned lines for a terminal.
template <int D>
std::string to_text(const MetricSummary<D>& s);

}  // namespace riemesh::cli
