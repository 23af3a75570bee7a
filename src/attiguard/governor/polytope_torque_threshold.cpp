#include "attiguard/governor/polytope_torque_threshold.hpp"

#include <cmath>
#include <string>

#include "attiguard/core/errors.hpp"

namespace attiguard::governor {

TorqueThreshold compute_polytope_torque_threshold(double kp, double kd, const lie::Mat3& J,
                                                  std::span<const lie::Vec3> rows,
                                                  std::span<const double> limits, int* slab) {
  if (rows.empty() || rows.size() != limits.size()) {
    throw SetupError("torque polytope: needs as many limits as rows (at least one)");
  }
  const lie::Mat3 J_inv = J.inverse();
  TorqueThreshold best;
  bool first = true;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const double norm = rows[i].norm();
    if (!(norm > 0.0) || !std::isfinite(norm) || !(limits[i] > 0.0) || !std::isfinite(limits[i])) {
      throw SetupError("torque polytope: row " + std::to_string(i) +
                       " must be non-zero and its limit positive and finite");
    }
    const lie::Vec3 n = rows[i] / norm;
    const TorqueThresholdInputs in{kp, kd, 1.0 / n.dot(J_inv * n), limits[i] / norm};
    const TorqueThreshold t = compute_torque_threshold(in);
    if (first || t.gamma_d < best.gamma_d) {
      best = t;
      first = false;
      if (slab) *slab = static_cast<int>(i);
    }
  }
  return best;
}

}  // namespace attiguard::governor
