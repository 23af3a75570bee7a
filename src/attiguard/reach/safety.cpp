#include "attiguard/reach/safety.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace attiguard::reach {

namespace {
double angle(const Vec3& a, const Vec3& b) {
  return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0));
}

}  // namespace

std::string violated_by_segment(const SafetySpec& spec, const TubeSegment& seg) {
  for (const PointingCone& c : spec.cones) {
    const double phi = angle(seg.attitude.center * c.axis_b, c.direction_i);
    const double rho = seg.attitude.radius;
    const bool ok = c.keep_out ? (phi - rho > c.half_angle) : (phi + rho < c.half_angle);
    if (!ok) return "cone '" + c.name + "'";
  }
  if (spec.omega_abs_max) {
    if (!(seg.omega.abs_max().array() < spec.omega_abs_max->array()).all()) return "omega_abs_max";
  }
  if (spec.omega_norm_max) {
    if (!(seg.omega_norm_bound() < *spec.omega_norm_max)) return "omega_norm_max";
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
