#pragma once
// A forward-mode dual number in two variables: a value and its gradient.
// The staged joint law evaluates its explicit update (slip and normal
// stress of a step -> dilation and strength) on these, so that the
// return mapping's Newton iteration and the law's consistent tangent get
// exact derivatives of the very functions the response is made of, not
// differences of them.
#include <cmath>

#include <Eigen/Core>

namespace rockface::mechanics {

struct Dual {
  double v = 0;
  Eigen::Vector2d d = Eigen::Vector2d::Zero();

  Dual() = default;
  Dual(double value) : v(value) {}  // NOLINT: constants mix freely with duals
  Dual(double value, const Eigen::Vector2d& grad) : v(value), d(grad) {}
  // The independent variable `index` (0 or 1) at `value`.
  static Dual variable(double value, int index) {
    Dual x(value);
    x.d(index) = 1;
    return x;
  }
};

inline Dual operator+(const Dual& a, const Dual& b) {
  return {a.v + b.v, a.d + b.d};
}
inline Dual operator-(const Dual& a, const Dual& b) {
  return {a.v - b.v, a.d - b.d};
}
inline Dual operator-(const Dual& a) {
  return {-a.v, -a.d};
}
inline Dual operator*(const Dual& a, const Dual& b) {
  return {a.v * b.v, b.v * a.d + a.v * b.d};
}
inline Dual operator/(const Dual& a, const Dual& b) {
  return {a.v / b.v, (a.d * b.v - a.v * b.d) / (b.v * b.v)};
}
inline Dual& operator+=(Dual& a, const Dual& b) {
  return a = a + b;
}

inline Dual tan(const Dual& a) {
  const double t = std::tan(a.v);
  return {t, (1 + t * t) * a.d};
}
inline Dual exp(const Dual& a) {
  const double e = std::exp(a.v);
  return {e, e * a.d};
}
// Only where a > 0 (the slope is infinite at 0).
inline Dual sqrt(const Dual& a) {
  const double s = std::sqrt(a.v);
  return {s, a.d / (2 * s)};
}
// The branch is chosen by value; the derivative is the chosen branch's.
inline const Dual& max(const Dual& a, const Dual& b) {
  return a.v >= b.v ? a : b;
}
inline const Dual& min(const Dual& a, const Dual& b) {
  return a.v <= b.v ? a : b;
}

}  // namespace rockface::mechanics
