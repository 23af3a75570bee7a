#pragma once
/// @file reference_schedule.hpp
/// A time-varying desired attitude R_d(t) (the PET-ERG paper, Sec. II, allows a "possibly
/// time-varying desired attitude trajectory"): a schedule of attitudes held piecewise constant,
/// or joined by constant-rate geodesic slews. Fixed capacity, allocation-free and noexcept to
/// evaluate.

#include <array>
#include <span>

#include "attiguard/core/name_table.hpp"
#include "attiguard/lie/so3.hpp"

namespace attiguard::governor {

using lie::Mat3;
using lie::Vec3;

/// Most waypoints of one schedule.
inline constexpr int kMaxWaypoints = 64;

/// How R_d moves between two waypoints.
enum class Interpolation {
  hold,      ///< R_d(t) = R_i on [t_i, t_{i+1}) (steps)
  geodesic,  ///< R_d(t) = R_i exp(s log(R_iᵀR_{i+1})), s = (t − t_i)/(t_{i+1} − t_i)
};

/// Names of Interpolation in scenario files (`[desired] interpolation`, docs/scenario-format.md).
inline constexpr NameTable<Interpolation, 2> kInterpolationNames{
    {{{Interpolation::hold, "hold"}, {Interpolation::geodesic, "geodesic"}}}};

/// One waypoint of a schedule: from time t on, the desired attitude is R_d (body → inertial).
struct Waypoint {
  double t{0.0};
  Mat3 R_d{Mat3::Identity()};
};

/// R_d(t) of the PET-ERG paper (Sec. II): R_before before the first waypoint's time (by default
/// the first waypoint's attitude), constant after the last.
class ReferenceSchedule {
 public:
  /// A constant desired attitude (the paper's Sec. V scenario).
  explicit ReferenceSchedule(const Mat3& R_d = Mat3::Identity()) noexcept;

  /// Waypoints with strictly increasing times (at most kMaxWaypoints, at least one).
  /// Throws SetupError (core/errors.hpp) otherwise (set-up code only).
  ReferenceSchedule(std::span<const Waypoint> waypoints, Interpolation interpolation);
  /// The same with R_d(t) = R_before for t < t_0, the first waypoint's time (a scenario's
  /// initial attitude: docs/scenario-format.md, "pet_erg", `[desired] schedule`).
  ReferenceSchedule(std::span<const Waypoint> waypoints, Interpolation interpolation,
                    const Mat3& R_before);

  /// R_d(t) [PET-ERG Sec. II]; allocation-free.
  [[nodiscard]] Mat3 at(double t) const noexcept;

  /// Number of waypoints of R_d(t) [PET-ERG Sec. II].
  [[nodiscard]] int size() const noexcept { return count_; }
  /// Waypoint i of R_d(t) [PET-ERG Sec. II].
  [[nodiscard]] const Waypoint& operator[](int i) const noexcept {
    return waypoints_[static_cast<std::size_t>(i)];
  }
  /// How R_d(t) moves between waypoints [PET-ERG Sec. II].
  [[nodiscard]] Interpolation interpolation() const noexcept { return interpolation_; }
  /// The final (steady-state) desired attitude R_d of Theorem 2 [PET-ERG Sec. IV-C].
  [[nodiscard]] const Mat3& final_attitude() const noexcept {
    return waypoints_[static_cast<std::size_t>(count_ - 1)].R_d;
  }

 private:
  std::array<Waypoint, kMaxWaypoints> waypoints_{};
  std::array<Vec3, kMaxWaypoints> slew_{};  ///< log(R_iᵀR_{i+1}) of each segment
  Mat3 before_{Mat3::Identity()};  ///< R_d(t) for t < waypoints_[0].t
  int count_{1};
  Interpolation interpolation_{Interpolation::hold};
};

}  // namespace attiguard::governor
