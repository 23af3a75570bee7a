#pragma once
/// @file scalar_interval.hpp
/// A closed real interval [lo, hi] with the four operations the Taylor-model bound of the
/// nominal's integration error needs (nominal_error.hpp). Round-to-nearest, like the rest of
/// ConReach's enclosures (docs/reach.md, "Limits": outward rounding is not used yet).

#include <algorithm>
#include <cmath>

namespace attiguard::reach {

struct Interval {
  double lo{0.0};
  double hi{0.0};

  constexpr Interval() = default;
  constexpr Interval(double v) : lo(v), hi(v) {}  // NOLINT: a point is an interval
  constexpr Interval(double l, double h) : lo(l), hi(h) {}

  /// max |x| over the interval.
  [[nodiscard]] double mag() const { return std::max(std::abs(lo), std::abs(hi)); }
  [[nodiscard]] bool finite() const { return std::isfinite(lo) && std::isfinite(hi); }

  friend Interval operator+(const Interval& a, const Interval& b) { return {a.lo + b.lo, a.hi + b.hi}; }
  friend Interval operator-(const Interval& a, const Interval& b) { return {a.lo - b.hi, a.hi - b.lo}; }
  friend Interval operator-(const Interval& a) { return {-a.hi, -a.lo}; }
  friend Interval operator*(const Interval& a, const Interval& b) {
    const double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
    return {std::min({p[0], p[1], p[2], p[3]}), std::max({p[0], p[1], p[2], p[3]})};
  }
  friend Interval operator/(const Interval& a, double d) {  // d > 0
    return {a.lo / d, a.hi / d};
  }
  Interval& operator+=(const Interval& b) { return *this = *this + b; }
};

/// |x| of a double, so that templates over double and Interval can bound magnitudes alike.
[[nodiscard]] inline double mag(double x) { return std::abs(x); }
[[nodiscard]] inline double mag(const Interval& x) { return x.mag(); }

}  // namespace attiguard::reach
