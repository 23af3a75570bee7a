#pragma once
/// @file pet_erg.hpp
/// The periodic event-triggered ERG [PET-ERG eqs. (5)-(6)]: the trigger condition is
/// evaluated only at the sampling instants t_k = t_0 + k·T_s and its outcome is held on
/// [t_k, t_{k+1}); inside an updating interval the reference moves by the continuous law [PET-ERG eq. (4)]
/// with the current Γ(t) − V(t) and ρ_n(t), otherwise it is held constant.

#include <cmath>

#include "attiguard/governor/continuous_erg.hpp"

namespace attiguard::governor {

/// Trigger condition [PET-ERG eq. (5)]: Γ(R_g(t_k)) − c_Γ V(t_k) ≥ 0.
[[nodiscard]] inline bool pet_trigger(double gamma, double V, double c_gamma) noexcept {
  return gamma - c_gamma * V >= 0.0;
}

/// Body rate ξ of the reference under [PET-ERG eq. (6)]:
/// ξ = κ (Γ − V) 1{(Γ − c_Γ V)(σ(t)) ≥ 0} ρ_n / max{‖ρ_n‖, ε}, where `flag` is the trigger
/// value of the current sampling interval (evaluated at σ(t) = t_k by pet_trigger).
[[nodiscard]] inline Vec3 pet_reference_rate(bool flag, double kappa, double gamma, double V,
                                             const Vec3& rho, double epsilon) noexcept {
  return flag ? erg_reference_rate(kappa, gamma, V, rho, epsilon) : Vec3::Zero();
}

/// The sampling clock of [PET-ERG eqs. (5)-(6)]: tells whether a sampling instant t_k = t_0 + k T_s has been
/// reached and keeps σ(t). Allocation-free; usable in a flight loop with any call rate.
class SamplingClock {
 public:
  /// Samples at 0, 1, 2, … (T_s = 1) until constructed otherwise [PET-ERG Sec. IV-A].
  SamplingClock() = default;
  /// Samples at t0, t0 + Ts, t0 + 2Ts, … (Ts > 0; PET-ERG paper Sec. IV-A).
  SamplingClock(double t0, double Ts) noexcept : t0_(t0), Ts_(Ts), next_index_(0) {}

  /// True when t has reached the next sampling instant (within 1e-9·T_s); advances past every
  /// instant ≤ t so that missed samples collapse into one (PET-ERG paper, σ(t) of [PET-ERG eq. (6)]).
  bool poll(double t) noexcept {
    if (!(t >= instant(next_index_) - 1e-9 * Ts_)) {
      return false;
    }
    const double k = std::floor((t - t0_) / Ts_ + 1e-9);
    last_index_ = static_cast<long>(k);
    next_index_ = last_index_ + 1;
    return true;
  }
  /// σ(t) of [PET-ERG eq. (6)]: the last sampling instant reached.
  [[nodiscard]] double last_sample() const noexcept { return instant(last_index_); }
  /// The next sampling instant t_{k+1} of [PET-ERG eq. (5)].
  [[nodiscard]] double next_sample() const noexcept { return instant(next_index_); }
  /// The sampling period T_s of [PET-ERG eqs. (5)-(6)].
  [[nodiscard]] double period() const noexcept { return Ts_; }

 private:
  [[nodiscard]] double instant(long k) const noexcept { return t0_ + static_cast<double>(k) * Ts_; }
  double t0_{0.0};
  double Ts_{1.0};
  long next_index_{0};
  long last_index_{0};
};

}  // namespace attiguard::governor
