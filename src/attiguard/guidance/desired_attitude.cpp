#include "attiguard/guidance/desired_attitude.hpp"

namespace attiguard::guidance {

DesiredAttitude desired_attitude(const GuidanceFrameSpec& spec, const Vec3& p_wp_i,
                                 const Vec3& p_i, const Vec3& v_i, const Vec3& a_i) noexcept {
  DesiredAttitude out;
  // (6): e^i = p_wp − p, so ė^i = −v^i for a fixed waypoint (the derivative (9) omits).
  const Vec3 e_i = spec.error_sign * (p_wp_i - p_i);
  const Vec3 e_dot_i = -spec.error_sign * v_i;
  out.error = error_frame(spec.q_ir, e_i, e_dot_i, spec.e_floor);
  if (spec.projection) {
    out.velocity = velocity_frame(out.error.q_ie, out.error.omega_e, v_i, a_i,
                                  spec.projection_sign, spec.projection_params);
  }
  out.q_id = lie::quat_multiply(out.error.q_ie, out.velocity.q_ed);                    // (23)
  const Mat3 R_ed = lie::quat_to_rotation(out.velocity.q_ed).transpose();             // R_e^d
  out.omega_d = R_ed * out.error.omega_e + out.velocity.omega_d;                       // (24)
  return out;
}

}  // namespace attiguard::guidance
