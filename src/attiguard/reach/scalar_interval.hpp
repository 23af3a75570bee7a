#pragma once
/// @file scalar_interval.hpp
/// A closed real interval [lo, hi] with outward-rounded operations: each result computed in
/// round-to-nearest is widened by one ulp on each side (the rounding error of one IEEE-754
/// operation is at most half an ulp), so it contains the exact result of the operation on any
/// reals in the operands (docs/reach.md, "Rigorous LMI check"). Used by the Taylor-model bound of
/// the nominal's integration error (nominal_error.hpp) and the LMI proof (lmi_proof.hpp).

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace attiguard::reach {

/// std::nextafter(x, +∞) without the libm call (docs/reach.md, "Rounding sites"; issue 48: the
/// call was a quarter of the paper example's analysis): finite nonzero x, the neighbouring bit
/// pattern; ±0, the smallest subnormal; NaN and +∞ unchanged; −∞ → −DBL_MAX. Bit for bit
/// nextafter's result (test RoundingNextUp).
[[nodiscard]] inline double next_up(double x) noexcept {
  if (x == 0.0) return std::numeric_limits<double>::denorm_min();
  if (!(x < HUGE_VAL)) return x;  // NaN, +∞
  const auto bits = std::bit_cast<std::uint64_t>(x);
  return std::bit_cast<double>(x > 0.0 ? bits + 1 : bits - 1);
}
/// std::nextafter(x, −∞) without the libm call: −next_up(−x) (docs/reach.md, "Rounding sites").
[[nodiscard]] inline double next_down(double x) noexcept { return -next_up(-x); }

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
  [[nodiscard]] static double down(double x) { return next_down(x); }
  [[nodiscard]] static double up(double x) { return next_up(x); }

  friend Interval operator+(const Interval& a, const Interval& b) {
    return {down(a.lo + b.lo), up(a.hi + b.hi)};
  }
  friend Interval operator-(const Interval& a, const Interval& b) {
    return {down(a.lo - b.hi), up(a.hi - b.lo)};
  }
  friend Interval operator-(const Interval& a) { return {-a.hi, -a.lo}; }  // exact
  /// The enclosure of a·b from the four end-point products; when an operand is a point, the
  /// two distinct products only (the same bits: min and max over repeated values).
  friend Interval operator*(const Interval& a, const Interval& b) {
    if (a.lo == a.hi) return point_times(a.lo, b);
    if (b.lo == b.hi) return point_times(b.lo, a);
    const double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
    return {down(std::min({p[0], p[1], p[2], p[3]})), up(std::max({p[0], p[1], p[2], p[3]}))};
  }
  /// x·b for a point x (operator*'s fast path).
  [[nodiscard]] static Interval point_times(double x, const Interval& b) {
    const double p0 = x * b.lo;
    const double p1 = x * b.hi;
    return {down(std::min(p0, p1)), up(std::max(p0, p1))};
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
