#include "attiguard/guidance/velocity_frame.hpp"

namespace attiguard::guidance {

VelocityFrame velocity_frame(const Quat& q_ie, const Vec3& omega_e, const Vec3& v_i,
                             const Vec3& a_i, double sign,
                             const VelocityProjectionParams& params) noexcept {
  VelocityFrame out;
  const Mat3 R_ie = lie::quat_to_rotation(q_ie).transpose();  // inertial → e
  const Vec3 v_e = R_ie * v_i;
  const Vec3 w = sign * v_e;
  const double speed = w.norm();
  if (!(speed > 1e-300) || !(params.blend_speed > 0.0) || !(params.cos_full > 0.0)) {
    return out;
  }
  const Vec3 w_dot = sign * (R_ie * a_i - omega_e.cross(v_e));
  const Vec3 u = w / speed;
  const Vec3 u_dot = (w_dot - u * u.dot(w_dot)) / speed;
  const Vec3 x = Vec3::UnitX();
  const double c = x.dot(u);
  const double c_dot = x.dot(u_dot);
  const Smoothstep s_v = smoothstep(speed / params.blend_speed);
  const Smoothstep s_c = smoothstep(c / params.cos_full);
  const double lambda = s_v.value * s_c.value;
  if (!(lambda > 0.0)) {
    return out;
  }
  const double lambda_dot = s_v.slope * u.dot(w_dot) / params.blend_speed * s_c.value +
                            s_v.value * s_c.slope * c_dot / params.cos_full;
  Quat n;
  n(0) = 1.0 + lambda * c;
  n.tail<3>() = lambda * x.cross(u);
  Quat n_dot;
  n_dot(0) = lambda_dot * c + lambda * c_dot;
  n_dot.tail<3>() = lambda_dot * x.cross(u) + lambda * x.cross(u_dot);
  out.q_ed = n / n.norm();
  out.omega_d = angular_velocity_of_unnormalised(n, n_dot);
  out.weight = lambda;
  return out;
}

}  // namespace attiguard::guidance
