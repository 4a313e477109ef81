#include "apps/metric_report.hpp"

#include <cmath>
#include <numbers>

namespace riemesh::cli {
namespace {

// Strings are built with += only: GCC 12 reports a false -Wrestrict on chains of operator+.
void add_num(std::string& out, double v, const char* fmt = "%.17g") {
  char buf[32];
  std::snprintf(buf, sizeof buf, fmt, v);
  out += buf;
}

/// Angle of a 2D direction in degrees, folded into (-90, 90] (a direction has no sign).
double angle_degrees(const Vec2& d) {
  double a = std::atan2(d[1], d[0]) * 180.0 / std::numbers::pi;
  if (a <= -90.0) a += 180.0;
  if (a > 90.0) a -= 180.0;
  return a;
}

/// Appends the numbers v[0..n) separated by sep.
template <class V>
void add_list(std::string& out, const V& v, int n, const char* sep, const char* fmt = "%.17g") {
  for (int i = 0; i < n; ++i) {
    if (i) out += sep;
    add_num(out, v[i], fmt);
  }
}

}  // namespace

template <int D>
std::string to_json(const MetricSummary<D>& s) {
  std::string j = "{\"metric\": [";
  add_list(j, s.metric.c, SymMat<D>::kSize, ", ");
  j += "], \"sizes\": [";
  add_list(j, s.sizes, D, ", ");
  j += "], \"directions\": [";
  for (int k = 0; k < D; ++k) {
    if (k) j += ", ";
    if constexpr (D == 2) {
      add_num(j, angle_degrees(s.directions.column(k)));
    } else {
      j += "[";
      add_list(j, s.directions.column(k), 3, ", ");
      j += "]";
    }
  }
  j += "], \"anisotropy\": ";
  add_num(j, s.anisotropy);
  j += ", \"det\": ";
  add_num(j, s.det);
  j += "}";
  return j;
}

template <int D>
std::string to_text(const MetricSummary<D>& s) {
  std::string t = D == 2 ? "metric (m11 m12 m22)         : " : "metric (m11 m12 m22 m13 m23 m33) : ";
  add_list(t, s.metric.c, SymMat<D>::kSize, " ");
  t += "\nsizes      : ";
  add_list(t, s.sizes, D, " ", "%.6g");
  t += "\ndirections : ";
  for (int k = 0; k < D; ++k) {
    if (k) t += ", ";
    if constexpr (D == 2) {
      add_num(t, angle_degrees(s.directions.column(k)), "%.6g");
      t += " deg";
    } else {
      t += "(";
      add_list(t, s.directions.column(k), 3, " ", "%.6g");
      t += ")";
    }
  }
  t += "\nanisotropy : ";
  add_num(t, s.anisotropy, "%.6g");
  t += "\ndet        : ";
  add_num(t, s.det, "%.6g");
  t += "\n";
  return t;
}

template std::string to_json(const MetricSummary<2>&);
template std::string to_json(const MetricSummary<3>&);
template std::string to_text(const MetricSummary<2>&);
template std::string to_text(const MetricSummary<3>&);

}  // namespace riemesh::cli
