#include "attiguard/reach/geodesic.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

#include "attiguard/core/errors.hpp"
#include "attiguard/integrate/integrator.hpp"
#include "attiguard/integrate/product_state.hpp"
#include "attiguard/reach/metrics.hpp"

namespace attiguard::reach {

Vec3 reduced_geodesic_rate(const Mat3& Q, const Vec3& w) {
  return -Q.ldlt().solve(w.cross(Q * w));
}

Mat3 chart_lambda(int chart) {
  static const std::array<Vec3, 4> s{Vec3(1, 1, 1), Vec3(1, -1, -1), Vec3(-1, 1, -1), Vec3(-1, -1, 1)};
  return s.at(static_cast<std::size_t>(chart)).asDiagonal();
}

Vec3 chart_coordinates(int chart, const Mat3& R) { return lie::log(chart_lambda(chart) * R); }

Mat3 chart_inverse(int chart, const Vec3& r) { return chart_lambda(chart) * lie::exp(r); }

int best_chart(const Mat3& R) {
  int best = 0;
  double best_norm = chart_coordinates(0, R).norm();
  for (int i = 1; i < 4; ++i) {
    const double n = chart_coordinates(i, R).norm();
    if (n < best_norm) {
      best = i;
      best_norm = n;
    }
  }
  return best;
}

Mat3 exp_atlas_f(const Vec3& r) {
  const double th = r.norm();
  const Mat3 rh = lie::hat(r);
  // 1/θ² − sin θ/(2θ(1 − cos θ)) → 1/12 + θ²/720 as θ → 0.
  double k;
  if (th < 1e-4) {
    k = 1.0 / 12.0 + th * th / 720.0;
  } else {
    k = 1.0 / (th * th) - std::sin(th) / (2.0 * th * (1.0 - std::cos(th)));
  }
  return Mat3::Identity() + 0.5 * rh + k * rh * rh;
}

double geodesic_steps(const Mat3& Q, const Vec3& w0) {
  const double kappa = lambda_max(Q) / lambda_min(Q);
  const double w_max = w0.norm() * std::sqrt(kappa);
  return std::ceil(10.0 * w_max * std::max(1.0, kappa - 1.0));
}

Mat3 geodesic_endpoint(const Mat3& Q, const Mat3& R0, const Vec3& w0, int steps) {
  using State = integrate::ProductState<1, 3>;
  const double needed = std::max(static_cast<double>(std::max(1, steps)), geodesic_steps(Q, w0));
  if (!(needed <= kMaxGeodesicSteps)) {
    std::ostringstream os;
    os << "geodesic [ConReach eq. (24)]: " << needed << " RKMK4 steps needed (|w0| = " << w0.norm()
       << ", condition " << lambda_max(Q) / lambda_min(Q) << "), more than " << kMaxGeodesicSteps;
    throw NumericalError(os.str());
  }
  State y;
  y.R[0] = R0;
  y.x = w0;
  integrate::IntegratorSettings s;
  s.method = integrate::Method::rkmk4;
  s.step = 1.0 / needed;
  integrate::RkmkIntegrator<State> integ(s);
  double t = 0.0;
  auto f = [&Q](double, const State& st) {
    State::Tangent d;
    d.head<3>() = st.x;
    d.tail<3>() = reduced_geodesic_rate(Q, st.x);
    return d;
  };
  integ.advance_to(f, y, t, 1.0, [](double, const State&) {});
  return y.R[0];
}

Vec3 chart_geodesic_endpoint(const Mat3& Q, int chart, const Vec3& r0, const Vec3& w0, int steps) {
  (void)chart;  // (26) is the same in every chart; only r0 depends on it
  using V6 = Eigen::Matrix<double, 6, 1>;
  auto rhs = [&Q](const V6& z) {
    const Vec3 r = z.head<3>();
    if (!(r.norm() < std::numbers::pi - 1e-6)) {
      std::ostringstream os;
      os << "metric ball leaves the exp chart (geodesic reaches ||r|| = " << r.norm()
         << " >= pi): the ball does not fit in a single chart; partition the initial set";
      throw NumericalError(os.str());
    }
    V6 d;
    d.head<3>() = exp_atlas_f(r) * z.tail<3>();
    d.tail<3>() = reduced_geodesic_rate(Q, z.tail<3>());
    return d;
  };
  V6 z;
  z << r0, w0;
  const int n = std::max(1, steps);
  const double h = 1.0 / n;
  for (int i = 0; i < n; ++i) {
    const V6 k1 = rhs(z);
    const V6 k2 = rhs(z + 0.5 * h * k1);
    const V6 k3 = rhs(z + 0.5 * h * k2);
    const V6 k4 = rhs(z + h * k3);
    z += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
  rhs(z);  // the endpoint too must lie in the chart
  return z.head<3>();
}

}  // namespace attiguard::reach
