#include "attiguard/reach/safety.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace attiguard::reach {

namespace {
double angle(const Vec3& a, const Vec3& b) {
  return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0));
}

/// Empty when the segment is proved safe, else the reason.
std::string check_segment(const SafetySpec& spec, const TubeSegment& seg) {
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
    if (!(seg.omega.norm_max() < *spec.omega_norm_max)) return "omega_norm_max";
  }
  return {};
}
}  // namespace

SafetyVerdict verify_safety(const SafetySpec& spec, const std::vector<ReachResult>& results) {
  SafetyVerdict v;
  v.requested = spec.requested();
  if (results.empty()) return v;
  v.step_safe.assign(results.front().steps.size(), true);
  if (!v.requested) {
    v.proved = true;
    return v;
  }
  for (const ReachResult& res : results) {
    for (std::size_t i = 0; i < res.steps.size(); ++i) {
      for (const TubeSegment& seg : res.steps[i].state_tube) {
        const std::string why = check_segment(spec, seg);
        if (why.empty()) continue;
        v.step_safe[i] = false;
        if (v.first_failure_time < 0.0 || seg.t0 < v.first_failure_time) {
          v.first_failure_time = seg.t0;
          std::ostringstream os;
          os << why << " cannot be proved on [" << seg.t0 << ", " << seg.t1 << "] s";
          v.reason = os.str();
        }
        break;
      }
    }
  }
  v.proved = v.first_failure_time < 0.0;
  return v;
}

}  // namespace attiguard::reach
