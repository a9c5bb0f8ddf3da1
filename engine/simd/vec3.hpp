// A 3-vector of a number type T (double or simd::Wide) for the contact law. The operations are
// written out in the order Eigen evaluates them on Vec3 (dot: (x x' + y y') + z z'; the
// cross product component by component), so a lane gets the bits Eigen gives for one contact.
#pragma once
#include "core/types.hpp"
#include "simd/wide.hpp"

namespace softpack {

template <class T>
struct V3 {
  T x, y, z;
};

template <class T>
[[gnu::always_inline]] inline V3<T> operator+(const V3<T>& a, const V3<T>& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
template <class T>
[[gnu::always_inline]] inline V3<T> operator-(const V3<T>& a, const V3<T>& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <class T>
[[gnu::always_inline]] inline V3<T> operator-(const V3<T>& a) {
  return {-a.x, -a.y, -a.z};
}
/// s a (also a s: IEEE products commute).
template <class T>
[[gnu::always_inline]] inline V3<T> operator*(const T& s, const V3<T>& a) {
  return {s * a.x, s * a.y, s * a.z};
}
template <class T>
[[gnu::always_inline]] inline V3<T> operator*(const V3<T>& a, const T& s) {
  return {a.x * s, a.y * s, a.z * s};
}
template <class T>
[[gnu::always_inline]] inline V3<T> operator/(const V3<T>& a, const T& s) {
  return {a.x / s, a.y / s, a.z / s};
}
template <class T>
[[gnu::always_inline]] inline T dot(const V3<T>& a, const V3<T>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <class T>
[[gnu::always_inline]] inline V3<T> cross(const V3<T>& a, const V3<T>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
/// m ? a : b, component by component.
template <class M, class T>
[[gnu::always_inline]] inline V3<T> select(const M& m, const V3<T>& a, const V3<T>& b) {
  return {simd::select(m, a.x, b.x), simd::select(m, a.y, b.y), simd::select(m, a.z, b.z)};
}

/// Every lane the same vector.
template <class T>
[[gnu::always_inline]] inline V3<T> broadcast(const Vec3& v) {
  return {T(v.x()), T(v.y()), T(v.z())};
}
[[gnu::always_inline]] inline V3<double> v3(const Vec3& v) { return {v.x(), v.y(), v.z()}; }
[[gnu::always_inline]] inline Vec3 vec3(const V3<double>& v) { return {v.x, v.y, v.z}; }

}  // namespace softpack
