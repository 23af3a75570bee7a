#include "attiguard/control/quaternion_pid.hpp"

namespace attiguard::control {

QuaternionPidOutput QuaternionPid::step(const lie::Quat& q_ib, const lie::Vec3& omega_b,
                                        const lie::Quat& q_id, const lie::Vec3& omega_d_d,
                                        double dt) noexcept {
  QuaternionPidOutput out;
  out.q_db = attitude_error(q_id, q_ib);                                   // (25)
  const double eta = out.q_db(0);
  const lie::Vec3 eps = out.q_db.tail<3>();
  const lie::Mat3 R_bd = lie::quat_to_rotation(out.q_db).transpose();      // R_d^b
  out.omega_db_b = omega_b - R_bd * omega_d_d;                             // (26)
  out.eps_dot = 0.5 * (eta * out.omega_db_b + eps.cross(out.omega_db_b));  // (26)
  const lie::Vec3 tau = -gains_.kp * eps - gains_.ki * integral_ - gains_.kd * out.eps_dot;  // (27)
  if (gains_.shaped) {
    // J ω̇ = S J_max (...) + the gyroscopic term ω × J ω cancelled (Euler's equation).
    const lie::Vec3 Jw = gains_.shaping_scale * (gains_.shaping * omega_b);
    out.tau_b = gains_.shaping * tau + omega_b.cross(Jw);
  } else {
    out.tau_b = tau;
  }
  if (!(gains_.integral_zone > 0.0) || eps.norm() < gains_.integral_zone) {
    integral_ += eps * dt;
  }
  return out;
}

}  // namespace attiguard::control
