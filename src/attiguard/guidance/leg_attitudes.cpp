#include "attiguard/guidance/leg_attitudes.hpp"

#include "attiguard/lie/shortest_arc.hpp"

namespace attiguard::guidance {

std::vector<LegAttitude> nominal_leg_attitudes(const lie::Mat3& R0_ib, const lie::Vec3& p0_i,
                                               std::span<const lie::Vec3> waypoints_i,
                                               double skip_below) {
  std::vector<LegAttitude> out;
  lie::Quat q = lie::rotation_to_quat(R0_ib);
  lie::Vec3 p = p0_i;
  const lie::Quat half_turn_z(0.0, 0.0, 0.0, 1.0);
  for (std::size_t k = 0; k < waypoints_i.size(); ++k) {
    const lie::Vec3 e = waypoints_i[k] - p;
    p = waypoints_i[k];
    if (!(e.norm() > skip_below)) continue;
    const lie::Mat3 R = lie::quat_to_rotation(q);
    const lie::Quat q_acc = lie::quat_multiply(lie::shortest_arc_quat(R.col(0), e), q);  // leg start
    const lie::Quat q_dec = lie::quat_multiply(q_acc, half_turn_z);                     // the flip
    out.push_back({static_cast<int>(k), false, lie::quat_to_rotation(q_acc)});
    out.push_back({static_cast<int>(k), true, lie::quat_to_rotation(q_dec)});
    q = q_dec;
  }
  return out;
}

}  // namespace attiguard::guidance
