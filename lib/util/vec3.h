#pragma once
// Small fixed-size vector math shared by mesh, trace, scene and render. Float for geometry (what
// Embree and the file formats store), double where sums need it.
#include <algorithm>
#include <cmath>
#include <limits>

namespace proxyvis {

template <typename T>
struct Vec3 {
  T x = 0, y = 0, z = 0;
  constexpr Vec3() = default;
  constexpr Vec3(T x_, T y_, T z_) : x(x_), y(y_), z(z_) {}
  template <typename U>
  constexpr explicit Vec3(const Vec3<U>& v) : x(T(v.x)), y(T(v.y)), z(T(v.z)) {}

  constexpr T operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  T& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr Vec3 operator+(const Vec3& o) const { return {x + o.x, y + o.y, z + o.z}; }
  constexpr Vec3 operator-(const Vec3& o) const { return {x - o.x, y - o.y, z - o.z}; }
  constexpr Vec3 operator-() const { return {-x, -y, -z}; }
  constexpr Vec3 operator*(T s) const { return {x * s, y * s, z * s}; }
  constexpr Vec3 operator/(T s) const { return {x / s, y / s, z / s}; }
  constexpr Vec3 operator*(const Vec3& o) const { return {x * o.x, y * o.y, z * o.z}; }
  Vec3& operator+=(const Vec3& o) {
    x += o.x;
    y += o.y;
    z += o.z;
    return *this;
  }
  Vec3& operator-=(const Vec3& o) {
    x -= o.x;
    y -= o.y;
    z -= o.z;
    return *this;
  }
  Vec3& operator*=(T s) {
    x *= s;
    y *= s;
    z *= s;
    return *this;
  }
  constexpr bool operator==(const Vec3& o) const { return x == o.x && y == o.y && z == o.z; }
};

using Vec3f = Vec3<float>;
using Vec3d = Vec3<double>;

template <typename T>
constexpr Vec3<T> operator*(T s, const Vec3<T>& v) {
  return v * s;
}
template <typename T>
constexpr T dot(const Vec3<T>& a, const Vec3<T>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <typename T>
constexpr Vec3<T> cross(const Vec3<T>& a, const Vec3<T>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <typename T>
T length(const Vec3<T>& v) {
  return std::sqrt(dot(v, v));
}
template <typename T>
Vec3<T> normalize(const Vec3<T>& v) {
  return v / length(v);
}
template <typename T>
Vec3<T> min(const Vec3<T>& a, const Vec3<T>& b) {
  return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
}
template <typename T>
Vec3<T> max(const Vec3<T>& a, const Vec3<T>& b) {
  return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
}
template <typename T>
bool isFinite(const Vec3<T>& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Axis-aligned box; empty until a point is added.
template <typename T>
struct Bounds3 {
  Vec3<T> lo{std::numeric_limits<T>::max(), std::numeric_limits<T>::max(),
             std::numeric_limits<T>::max()};
  Vec3<T> hi{std::numeric_limits<T>::lowest(), std::numeric_limits<T>::lowest(),
             std::numeric_limits<T>::lowest()};
  bool empty() const { return lo.x > hi.x; }
  void extend(const Vec3<T>& p) {
    lo = min(lo, p);
    hi = max(hi, p);
  }
  void extend(const Bounds3& b) {
    lo = min(lo, b.lo);
    hi = max(hi, b.hi);
  }
  // True when the two boxes share a point (touching counts).
  bool overlaps(const Bounds3& b) const {
    return lo.x <= b.hi.x && b.lo.x <= hi.x && lo.y <= b.hi.y && b.lo.y <= hi.y && lo.z <= b.hi.z &&
           b.lo.z <= hi.z;
  }
  Vec3<T> center() const { return (lo + hi) * T(0.5); }
  Vec3<T> extent() const { return hi - lo; }
  T diagonal() const { return empty() ? T(0) : length(hi - lo); }
};
using Bounds3f = Bounds3<float>;
using Bounds3d = Bounds3<double>;

}  // namespace proxyvis
