#pragma once
// The statistics that end every remeshing pass (2D, 3D), gathered the same way whatever the mesh:
// metric edge lengths and element qualities into PassStats, and the worst edge for the stall
// message.
#include <algorithm>
#include <cstdio>
#include <limits>
#include <string>

#include "core/format.hpp"
#include "core/vec.hpp"
#include "remesh/adapt2d.hpp"

namespace riemesh {

/// Feed edge(l) for every edge and element(q) for every element, then fill().
struct PassSummary {
  long edges = 0, in_band = 0, elements = 0;
  double sum = 0, lmin = std::numeric_limits<double>::infinity(), lmax = 0;
  double qsum = 0, qmin = 1.0;

  void edge(double l) {
    ++edges, sum += l, lmin = std::min(lmin, l), lmax = std::max(lmax, l);
    in_band += (l >= 0.7071067811865476 && l <= 1.4142135623730951) ? 1 : 0;
  }
  void element(double q) { ++elements, qsum += q, qmin = std::min(qmin, q); }
  /// Lengths and qualities into st, with the live counts.
  void fill(PassStats& st, std::size_t vertices, std::size_t live_elements) const {
    st.vertices = vertices;
    st.triangles = live_elements;
    st.len_min = lmin, st.len_max = lmax, st.len_mean = edges ? sum / edges : 0.0;
    st.len_in = edges ? static_cast<double>(in_band) / edges : 0.0;
    st.q_min = qmin, st.q_mean = elements ? qsum / elements : 0.0;
  }
};

/// How far an edge of metric length l is from unit: l or 1/l.
inline double length_badness(double l) { return l > 1.0 ? l : 1.0 / l; }

/// "an edge stays too long (metric length L) near (x, y[, z]): ..." for the worst edge left.
template <int D>
std::string stall_message(double length, const Vec<D>& midpoint) {
  std::string s = length > 1.0 ? "an edge stays too long" : "an edge stays too short";
  s += " (metric length ";
  s += format_g(length);
  s += ") near (";
  for (int i = 0; i < D; ++i) {
    if (i > 0) s += ", ";
    s += format_g(midpoint[i]);
  }
  s += "): the operators' checks refuse to change it further";
  return s;
}

}  // namespace riemesh
