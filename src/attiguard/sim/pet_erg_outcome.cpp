#include "attiguard/sim/pet_erg_outcome.hpp"

#include <algorithm>

namespace attiguard::sim {

void ReferenceMotion::observe(double t, const lie::Mat3& R_g) noexcept {
  if (t < t_start_) return;
  if (!started_) {
    started_ = true;
    first_ = R_g;
    last_ = R_g;
    return;
  }
  // R_g held (the same bits): log(RᵀR) is rounding, below kReferenceMoveFloor, not a move.
  if (R_g == last_) {
    last_ = R_g;  // the same values; keeps the signs of zeros as the path below would
    return;
  }
  const lie::Vec3 move = lie::log(last_.transpose() * R_g);
  last_ = R_g;
  const double size = move.norm();
  if (!(size > kReferenceMoveFloor)) return;
  ++moves_;
  path_length_ += size;
  largest_move_ = std::max(largest_move_, size);
  if (last_move_.dot(move) < 0.0) ++reversals_;
  last_move_ = move;
}

double ReferenceMotion::displacement() const noexcept {
  return started_ ? lie::distance(first_, last_) : 0.0;
}

PetErgOutcome classify_outcome(const OutcomeEvidence& e) noexcept {
  if (e.convergence_time >= 0.0) return PetErgOutcome::converged;
  if (!e.governed) return PetErgOutcome::not_converged_by_end;
  const ReferenceMotion& m = e.last_half;
  if (m.reversals() >= 2 && m.path_length() >= 10.0 * e.distance_tolerance &&
      m.path_length() >= 4.0 * m.displacement()) {
    return PetErgOutcome::chattering;
  }
  if (e.distance_left > e.distance_tolerance && m.displacement() < 0.01 * e.distance_left) {
    return PetErgOutcome::stalled;
  }
  return PetErgOutcome::not_converged_by_end;
}

}  // namespace attiguard::sim
