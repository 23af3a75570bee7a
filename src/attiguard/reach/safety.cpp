#include "attiguard/reach/safety.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include "attiguard/reach/interval_matrix.hpp"

namespace attiguard::reach {

namespace {
double angle(const Vec3& a, const Vec3& b) {
  return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0));
}

/// Enclosure of cos φ, φ the angle between R_c a and d, for the floating-point numbers (not
/// acos of a rounded normalised dot product): (R_c a)·d / (‖R_c a‖ ‖d‖) in intervals.
Interval cos_angle(const Mat3& Rc, const Vec3& a, const Vec3& d) {
  const IVec3 v = mat_vec(point<3>(Rc), point(a));
  const IVec3 di = point(d);
  const Interval num = dot(v, di);
  const Interval n2 = dot(v, v) * dot(di, di);
  const double den_lo = sqrt_down(n2.lo);
  const double den_hi = sqrt_up(n2.hi);
  if (!(den_lo > 0.0) || !num.finite() || !std::isfinite(den_hi)) return {-1.0, 1.0};
  // num / den over den ∈ [den_lo, den_hi] > 0: the extremes are at the ends.
  const double lo = num.lo >= 0.0 ? (Interval(num.lo) / den_hi).lo : (Interval(num.lo) / den_lo).lo;
  const double hi = num.hi >= 0.0 ? (Interval(num.hi) / den_lo).hi : (Interval(num.hi) / den_hi).hi;
  return {std::max(lo, -1.0), std::min(hi, 1.0)};
}

/// cos of the C library taken as accurate to 1 ulp, widened by 2 ulps.
double cos_down(double x) { return Interval::down(Interval::down(std::cos(x))); }
double cos_up(double x) { return Interval::up(Interval::up(std::cos(x))); }

/// Proves for every rotation R with d(R, U) ≤ ρ, U the polar factor of the floating-point
/// centre R_c, that angle(R a, d) > α (keep-out) or < α (keep-in) (docs/reach.md, "Rounding
/// sites"). angle(R a, d) is within ρ of angle(U a, d) (safety.hpp), and U a within
/// asin(e) ≤ (π/2) e of R_c a, e = ‖R_cᵀR_c − I‖_F ≥ ‖R_c − U‖₂. With φ = angle(R_c a, d) and
/// β = α ± (ρ + (π/2) e) in [0, π], φ > β ⇔ cos φ < cos β (keep-out) and φ < β ⇔ cos φ > cos β.
bool cone_proved(const PointingCone& c, const AttitudeBall& att) {
  // rounding site: cone-angle
  const double e = orthogonality_defect_up(point<3>(att.center));
  if (!(e < 1.0) || !(att.radius >= 0.0)) return false;
  const Interval half_pi_e = Interval(Interval::up(0.5 * std::numbers::pi)) * Interval(e);
  const Interval allowance = Interval(att.radius) + half_pi_e;
  const Interval cos_phi = cos_angle(att.center, c.axis_b, c.direction_i);
  if (c.keep_out) {
    const double beta = (Interval(c.half_angle) + allowance).hi;  // ≥ α + allowance
    if (!(beta <= std::numbers::pi)) return false;               // the float π is below π
    return cos_phi.hi < cos_down(beta);
  }
  const double beta = (Interval(c.half_angle) - allowance).lo;  // ≤ α − allowance
  if (!(beta > 0.0)) return false;
  return cos_phi.lo > cos_up(std::min(beta, std::numbers::pi));
}

/// Upper bound of the box's max ‖ω‖ (the corner of largest |ω_k|): √ of an upward sum of squares.
double norm_max_up(const Box3& box) {
  // rounding site: omega-norm-check
  const Vec3 m = box.abs_max();  // exact
  return sqrt_up(dot(point(m), point(m)).hi);
}

}  // namespace

std::string violated_by_segment(const SafetySpec& spec, const TubeSegment& seg) {
  for (const PointingCone& c : spec.cones) {
    if (!cone_proved(c, seg.attitude)) return "cone '" + c.name + "'";
  }
  if (spec.omega_abs_max) {
    // |ω_k| and the comparison are exact.
    if (!(seg.omega.abs_max().array() < spec.omega_abs_max->array()).all()) return "omega_abs_max";
  }
  if (spec.omega_norm_max) {
    // rounding site: omega-norm-check
    const double bound = std::min(seg.omega_norm, norm_max_up(seg.omega));
    if (!(bound < *spec.omega_norm_max)) return "omega_norm_max";
  }
  return {};
}

std::string violated_by_state(const SafetySpec& spec, const Mat3& R, const Vec3& omega) {
  for (const PointingCone& c : spec.cones) {
    const double phi = angle(R * c.axis_b, c.direction_i);
    if (c.keep_out ? !(phi > c.half_angle) : !(phi < c.half_angle)) return "cone '" + c.name + "'";
  }
  if (spec.omega_abs_max && !(omega.cwiseAbs().array() < spec.omega_abs_max->array()).all()) return "omega_abs_max";
  if (spec.omega_norm_max && !(omega.norm() < *spec.omega_norm_max)) return "omega_norm_max";
  return {};
}

SafetyVerdict verify_safety(const SafetySpec& spec, const std::vector<ReachResult>& results) {
  SafetyVerdict v;
  v.requested = spec.requested();
  if (results.empty()) return v;
  v.step_safe.assign(results.front().steps.size(), true);
  auto fail = [&v](double t, const std::string& reason) {
    if (v.first_failure_time < 0.0 || t < v.first_failure_time) {
      v.first_failure_time = t;
      v.reason = reason;
    }
  };
  for (const ReachResult& res : results) {
    // An analysis that stopped early proves nothing from its stop on (conreach.hpp).
    if (!res.complete) {
      v.complete = false;
      std::ostringstream os;
      os << "the analysis stopped at t = " << res.stop_time << " s: " << res.stop_reason;
      fail(res.stop_time, os.str());
    }
    if (!v.requested) continue;
    for (std::size_t i = 0; i < res.steps.size(); ++i) {
      for (const TubeSegment& seg : res.steps[i].state_tube) {
        const std::string why = violated_by_segment(spec, seg);
        if (why.empty()) continue;
        if (&res == &results.front()) v.step_safe[i] = false;
        std::ostringstream os;
        os << why << " cannot be proved on [" << seg.t0 << ", " << seg.t1 << "] s";
        fail(seg.t0, os.str());
        break;
      }
    }
  }
  v.proved = v.first_failure_time < 0.0;
  return v;
}

}  // namespace attiguard::reach
