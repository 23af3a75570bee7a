#include "attiguard/reach/nominal_error.hpp"

#include <cmath>
#include <limits>
#include <vector>

#include "attiguard/reach/scalar_interval.hpp"

namespace attiguard::reach {

namespace {

constexpr int kMaxOrder = 30;

template <class T>
using Rot = std::array<T, 9>;  // R row by row
template <class T>
using Vel = std::array<T, 3>;

/// Taylor coefficients x_[k] = x^(k)(s)/k!, k = 0..order, of the solution of Ṙ = R ω̂,
/// ω̇ = X_ω(R, ω) through (R0, ω0), by the exact recursion of the polynomial field:
///   ω_[k+1] = X_[k]/(k+1),  R_[k+1] = Σ_{i≤k} R_[i] (ω_[k−i])^ / (k+1),
/// with X_[k] = c δ_k0 + B ω_[k] + Σ_{i≤k} (ω_[i]ᵀ Q_a ω_[k−i])_a + L vec(R_[k]).
/// With T = Interval and (R0, ω0) an enclosure of every point of an a-priori set, the order-k
/// coefficient encloses x^(k)(ξ)/k! of every solution through that set.
template <class T>
void taylor_coefficients(const PolynomialField& f, const Rot<T>& R0, const Vel<T>& w0, int order,
                         std::vector<Rot<T>>& R, std::vector<Vel<T>>& w) {
  R.assign(static_cast<std::size_t>(order) + 1, Rot<T>{});
  w.assign(static_cast<std::size_t>(order) + 1, Vel<T>{});
  R[0] = R0;
  w[0] = w0;
  for (int k = 0; k < order; ++k) {
    const auto ku = static_cast<std::size_t>(k);
    const double inv = static_cast<double>(k + 1);
    for (int a = 0; a < 3; ++a) {
      T x = (k == 0) ? T(f.constant(a)) : T(0.0);
      for (int b = 0; b < 3; ++b) x += T(f.linear(a, b)) * w[ku][static_cast<std::size_t>(b)];
      for (int m = 0; m < 9; ++m) x += T(f.linear_R(a, m)) * R[ku][static_cast<std::size_t>(m)];
      const lie::Mat3& Q = f.quadratic[static_cast<std::size_t>(a)];
      if (!Q.isZero(0.0)) {
        for (std::size_t i = 0; i <= ku; ++i) {
          for (int b = 0; b < 3; ++b) {
            T row(0.0);
            for (int c = 0; c < 3; ++c) row += T(Q(b, c)) * w[ku - i][static_cast<std::size_t>(c)];
            x += w[i][static_cast<std::size_t>(b)] * row;
          }
        }
      }
      w[ku + 1][static_cast<std::size_t>(a)] = x / inv;
    }
    for (int r = 0; r < 3; ++r) {
      for (int s = 0; s < 3; ++s) {
        T x(0.0);
        for (std::size_t i = 0; i <= ku; ++i) {
          const Vel<T>& v = w[ku - i];
          const Rot<T>& Ri = R[i];
          // (R v̂)_rs = Σ_m R_rm v̂_ms with v̂ = [[0, −v3, v2], [v3, 0, −v1], [−v2, v1, 0]].
          const auto at = [&](int m) { return Ri[static_cast<std::size_t>(3 * r + m)]; };
          switch (s) {
            case 0: x += at(1) * v[2] - at(2) * v[1]; break;
            case 1: x += at(2) * v[0] - at(0) * v[2]; break;
            default: x += at(0) * v[1] - at(1) * v[0]; break;
          }
        }
        R[ku + 1][static_cast<std::size_t>(3 * r + s)] = x / inv;
      }
    }
  }
}

/// The initial values of the two Taylor recursions: the point p0 and an interval enclosure of
/// the a-priori set — entries of R with d(R, R0) ≤ ρ satisfy |R_rs − R0_rs| ≤ ‖R − R0‖₂ =
/// 2 sin(ρ/2) and |R_rs| ≤ 1.
struct TaylorStart {
  Rot<double> Rp{};
  Vel<double> wp{};
  Rot<Interval> Ri{};
  Vel<Interval> wi{};
};

TaylorStart taylor_start(const lie::Mat3& R0, const lie::Vec3& omega0, const Box3& omega_box,
                         double attitude_radius) {
  TaylorStart st;
  const double chord_R = chord(attitude_radius);
  for (int r = 0; r < 3; ++r) {
    for (int s = 0; s < 3; ++s) {
      const double c = R0(r, s);
      st.Rp[static_cast<std::size_t>(3 * r + s)] = c;
      st.Ri[static_cast<std::size_t>(3 * r + s)] = {std::max(-1.0, c - chord_R), std::min(1.0, c + chord_R)};
    }
  }
  for (int a = 0; a < 3; ++a) {
    st.wp[static_cast<std::size_t>(a)] = omega0(a);
    st.wi[static_cast<std::size_t>(a)] = {omega_box.lo(a), omega_box.hi(a)};
  }
  return st;
}

/// Point coefficients at p0 (Rc, wc) and interval coefficients over the a-priori set (Rr, wr).
struct TaylorSeries {
  std::vector<Rot<double>> Rc;
  std::vector<Vel<double>> wc;
  std::vector<Rot<Interval>> Rr;
  std::vector<Vel<Interval>> wr;
};

/// Order p: the lowest whose remainder is below the rounding level of the state, otherwise the
/// one with the smallest remainder (orders up to 12 first, up to kMaxOrder if needed); −1 when
/// no remainder is finite. Leaves in `series` the coefficients of the last order range tried.
int taylor_order(const PolynomialField& field, const TaylorStart& st, double h, TaylorSeries& series) {
  const double u = std::numeric_limits<double>::epsilon();
  double scale = 1.0;
  for (const double x : st.Rp) scale = std::max(scale, std::abs(x));
  for (const double x : st.wp) scale = std::max(scale, std::abs(x));
  int best_p = -1;
  for (const int max_order : {12, kMaxOrder}) {
    taylor_coefficients(field, st.Rp, st.wp, max_order, series.Rc, series.wc);
    taylor_coefficients(field, st.Ri, st.wi, max_order + 1, series.Rr, series.wr);
    best_p = -1;
    double best_rem = std::numeric_limits<double>::infinity();
    bool converged = false;
    for (int p = 2; p <= max_order && !converged; ++p) {
      const auto pu = static_cast<std::size_t>(p);
      const double hp1 = std::pow(h, p + 1);
      double rem = 0.0;
      for (const Interval& x : series.Rr[pu + 1]) rem = std::max(rem, x.mag() * hp1);
      for (const Interval& x : series.wr[pu + 1]) rem = std::max(rem, x.mag() * hp1);
      if (!std::isfinite(rem)) continue;
      if (rem < best_rem) {
        best_rem = rem;
        best_p = p;
      }
      converged = rem <= u * scale;
    }
    if (converged) break;
  }
  return best_p;
}

/// The order-p Taylor polynomial of one state entry evaluated at h, against the computed value:
/// |x*(s+h) − computed| ≤ |T_p(h) − computed| + remainder + rounding of T_p and of the
/// subtraction (γ·(Σ_k |x_[k]| h^k + |computed|)).
class EntryError {
 public:
  EntryError(int order, double h)
      : pu_(static_cast<std::size_t>(order)),
        h_(h),
        hp1_(std::pow(h, order + 1)),
        gamma_(4.0 * (order + 2) * kU / (1.0 - 4.0 * (order + 2) * kU)) {}

  /// `value_at(k)`: the point coefficient x_[k]; `remainder`: the magnitude of the interval
  /// coefficient of order p+1.
  template <class ValueAt>
  double operator()(const ValueAt& value_at, double remainder, double computed) {
    double value = 0.0;
    double magnitude = 0.0;
    double hk = 1.0;
    for (std::size_t k = 0; k <= pu_; ++k) {
      const double term = value_at(k) * hk;
      value += term;
      magnitude += std::abs(term);
      hk *= h_;
    }
    const double rem = remainder * hp1_;
    largest_remainder = std::max(largest_remainder, rem);
    return std::abs(value - computed) + rem + gamma_ * (magnitude + std::abs(computed));
  }

  double largest_remainder{0.0};

 private:
  static constexpr double kU = std::numeric_limits<double>::epsilon();
  std::size_t pu_;
  double h_;
  double hp1_;
  double gamma_;
};

}  // namespace

std::optional<NominalStepError> nominal_step_error(const PolynomialField& field, const lie::Mat3& R0,
                                                   const lie::Vec3& omega0, const lie::Mat3& R1,
                                                   const lie::Vec3& omega1, double h,
                                                   const Box3& omega_box, double attitude_radius,
                                                   std::string& why) {
  if (!(h > 0.0) || !std::isfinite(h)) {
    why = "sub-step length is not a positive number";
    return std::nullopt;
  }
  TaylorSeries series;
  const int best_p = taylor_order(field, taylor_start(R0, omega0, omega_box, attitude_radius), h, series);
  if (best_p < 0) {
    why = "the Taylor remainder of the nominal is not finite over the a-priori enclosure";
    return std::nullopt;
  }
  // Evaluate the order-p polynomial at h, with magnitudes for the rounding term.
  const auto rem = static_cast<std::size_t>(best_p) + 1;
  const double u = std::numeric_limits<double>::epsilon();
  EntryError entry(best_p, h);
  NominalStepError out;
  out.order = best_p;
  Vel<double> dw{};
  for (std::size_t a = 0; a < 3; ++a) {
    dw[a] = entry([&](std::size_t k) { return series.wc[k][a]; }, series.wr[rem][a].mag(),
                  omega1(static_cast<int>(a)));
    out.bound.d_omega_b(static_cast<int>(a)) = dw[a];
  }
  out.bound.e_omega_b = std::sqrt(dw[0] * dw[0] + dw[1] * dw[1] + dw[2] * dw[2]) * (1.0 + 4.0 * u);
  double frob2 = 0.0;
  for (std::size_t m = 0; m < 9; ++m) {
    const double e = entry([&](std::size_t k) { return series.Rc[k][m]; }, series.Rr[rem][m].mag(),
                           R1(static_cast<int>(m / 3), static_cast<int>(m % 3)));
    frob2 += e * e;
  }
  out.remainder = entry.largest_remainder;
  // Both R*(s+h) and R1 are rotations: ‖R* − R1‖₂ = 2 sin(θ/2) ≤ ‖R* − R1‖_F, θ = d(R*, R1).
  const double frob = std::sqrt(frob2) * (1.0 + 4.0 * u);
  if (!std::isfinite(frob) || !(frob < 2.0) || !out.bound.all_finite()) {
    why = "the nominal's error bound is not finite or exceeds the diameter of SO(3)";
    return std::nullopt;
  }
  out.bound.e_R = 2.0 * std::asin(0.5 * frob) * (1.0 + 4.0 * u);
  return out;
}

}  // namespace attiguard::reach
