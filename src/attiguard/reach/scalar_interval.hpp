#pragma once
/// @file scalar_interval.hpp
/// A closed real interval [lo, hi] with outward-rounded operations: each result computed in
/// round-to-nearest is widened by one ulp on each side (the rounding error of one IEEE-754
/// operation is at most half an ulp), so it contains the exact result of the operation on any
/// reals in the operands (docs/reach.md, "Rigorous LMI check"). Used by the Taylor-model bound of
/// the nominal's integration error (nominal_error.hpp) and the LMI proof (lmi_proof.hpp).

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

  /// One ulp below / above (the outward rounding of one operation).
  [[nodiscard]] static double down(double x) { return std::nextafter(x, -HUGE_VAL); }
  [[nodiscard]] static double up(double x) { return std::nextafter(x, HUGE_VAL); }

  friend Interval operator+(const Interval& a, const Interval& b) {
    return {down(a.lo + b.lo), up(a.hi + b.hi)};
  }
  friend Interval operator-(const Interval& a, const Interval& b) {
    return {down(a.lo - b.hi), up(a.hi - b.lo)};
  }
  friend Interval operator-(const Interval& a) { return {-a.hi, -a.lo}; }  // exact
  friend Interval operator*(const Interval& a, const Interval& b) {
    const double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
    return {down(std::min({p[0], p[1], p[2], p[3]})), up(std::max({p[0], p[1], p[2], p[3]}))};
  }
  friend Interval operator/(const Interval& a, double d) {  // d > 0
    return {down(a.lo / d), up(a.hi / d)};
  }
  Interval& operator+=(const Interval& b) { return *this = *this + b; }
};

/// |x| of a double, so that templates over double and Interval can bound magnitudes alike.
[[nodiscard]] inline double mag(double x) { return std::abs(x); }
[[nodiscard]] inline double mag(const Interval& x) { return x.mag(); }

}  // namespace attiguard::reach
