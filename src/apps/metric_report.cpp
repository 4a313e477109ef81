#include "apps/metric_report.hpp"

#include <cmath>
#include <numbers>

namespace riemesh::cli {
namespace {

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string short_num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

/// Angle of a 2D direction in degrees, folded into (-90, 90] (a direction has no sign).
double angle_degrees(const Vec2& d) {
  double a = std::atan2(d[1], d[0]) * 180.0 / std::numbers::pi;
  if (a <= -90.0) a += 180.0;
  if (a > 90.0) a -= 180.0;
  return a;
}

template <class F>
std::string join(int n, F f, const char* sep) {
  std::string out;
  for (int i = 0; i < n; ++i) out += (i ? sep : "") + f(i);
  return out;
}

}  // namespace

template <int D>
std::string to_json(const MetricSummary<D>& s) {
  constexpr int n = SymMat<D>::kSize;
  std::string j = "{\"metric\": [" + join(n, [&](int k) { return num(s.metric.c[k]); }, ", ");
  j += "], \"sizes\": [" + join(D, [&](int k) { return num(s.sizes[k]); }, ", ");
  j += "], \"directions\": [";
  if constexpr (D == 2) {
    j += join(2, [&](int k) { return num(angle_degrees(s.directions.column(k))); }, ", ");
  } else {
    j += join(3, [&](int k) {
      const Vec3 v = s.directions.column(k);
      return "[" + num(v[0]) + ", " + num(v[1]) + ", " + num(v[2]) + "]";
    }, ", ");
  }
  j += "], \"anisotropy\": " + num(s.anisotropy) + ", \"det\": " + num(s.det) + "}";
  return j;
}

template <int D>
std::string to_text(const MetricSummary<D>& s) {
  constexpr int n = SymMat<D>::kSize;
  std::string t = std::string("metric     ") + (D == 2 ? "(m11 m12 m22)" : "(m11 m12 m22 m13 m23 m33)");
  t += ": " + join(n, [&](int k) { return num(s.metric.c[k]); }, " ") + "\n";
  t += "sizes      : " + join(D, [&](int k) { return short_num(s.sizes[k]); }, " ") + "\n";
  if constexpr (D == 2) {
    t += "directions : " +
         join(2, [&](int k) { return short_num(angle_degrees(s.directions.column(k))) + " deg"; },
              ", ") + "\n";
  } else {
    t += "directions : " + join(3, [&](int k) {
      const Vec3 v = s.directions.column(k);
      return "(" + short_num(v[0]) + " " + short_num(v[1]) + " " + short_num(v[2]) + ")";
    }, " ") + "\n";
  }
  t += "anisotropy : " + short_num(s.anisotropy) + "\n";
  t += "det        : " + short_num(s.det) + "\n";
  return t;
}

template std::string to_json(const MetricSummary<2>&);
template std::string to_json(const MetricSummary<3>&);
template std::string to_text(const MetricSummary<2>&);
template std::string to_text(const MetricSummary<3>&);

}  // namespace riemesh::cli
