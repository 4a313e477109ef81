#pragma once
// Fixed-size vectors Vec<D>, D = 2 or 3: a trivially copyable aggregate with value semantics.
#include <cmath>
#include <cstddef>

namespace riemesh {

template <int D>
struct Vec {
  static_assert(D >= 1 && D <= 4, "Vec<D> is meant for small D");
  double x[D];

  constexpr double& operator[](int i) { return x[i]; }
  constexpr const double& operator[](int i) const { return x[i]; }

  static constexpr Vec zero() {
    Vec v{};
    for (int i = 0; i < D; ++i) v.x[i] = 0.0;
    return v;
  }
  /// The i-th unit vector.
  static constexpr Vec unit(int i) {
    Vec v = zero();
    v.x[i] = 1.0;
    return v;
  }
  friend constexpr bool operator==(const Vec&, const Vec&) = default;
};

using Vec2 = Vec<2>;
using Vec3 = Vec<3>;

template <int D>
constexpr Vec<D> operator+(const Vec<D>& a, const Vec<D>& b) {
  Vec<D> r{};
  for (int i = 0; i < D; ++i) r[i] = a[i] + b[i];
  return r;
}
template <int D>
constexpr Vec<D> operator-(const Vec<D>& a, const Vec<D>& b) {
  Vec<D> r{};
  for (int i = 0; i < D; ++i) r[i] = a[i] - b[i];
  return r;
}
template <int D>
constexpr Vec<D> operator-(const Vec<D>& a) {
  Vec<D> r{};
  for (int i = 0; i < D; ++i) r[i] = -a[i];
  return r;
}
template <int D>
constexpr Vec<D> operator*(double s, const Vec<D>& a) {
  Vec<D> r{};
  for (int i = 0; i < D; ++i) r[i] = s * a[i];
  return r;
}
template <int D>
constexpr Vec<D> operator*(const Vec<D>& a, double s) {
  return s * a;
}
template <int D>
constexpr Vec<D> operator/(const Vec<D>& a, double s) {
  Vec<D> r{};
  for (int i = 0; i < D; ++i) r[i] = a[i] / s;
  return r;
}
template <int D>
constexpr Vec<D>& operator+=(Vec<D>& a, const Vec<D>& b) {
  for (int i = 0; i < D; ++i) a[i] += b[i];
  return a;
}
template <int D>
constexpr Vec<D>& operator-=(Vec<D>& a, const Vec<D>& b) {
  for (int i = 0; i < D; ++i) a[i] -= b[i];
  return a;
}
template <int D>
constexpr Vec<D>& operator*=(Vec<D>& a, double s) {
  for (int i = 0; i < D; ++i) a[i] *= s;
  return a;
}

template <int D>
constexpr double dot(const Vec<D>& a, const Vec<D>& b) {
  double s = 0.0;
  for (int i = 0; i < D; ++i) s += a[i] * b[i];
  return s;
}
template <int D>
inline double norm(const Vec<D>& a) {
  return std::sqrt(dot(a, a));
}
template <int D>
inline Vec<D> normalize(const Vec<D>& a) {
  return a / norm(a);
}
constexpr Vec3 cross(const Vec3& a, const Vec3& b) {
  return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}
/// z-component of the 2D cross product (twice the signed area of (0, a, b)).
constexpr double cross(const Vec2& a, const Vec2& b) { return a[0] * b[1] - a[1] * b[0]; }

}  // namespace riemesh
