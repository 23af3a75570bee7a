#include "attiguard/governor/reference_schedule.hpp"

#include "attiguard/core/errors.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace attiguard::governor {

ReferenceSchedule::ReferenceSchedule(const Mat3& R_d) noexcept {
  waypoints_[0] = {0.0, R_d};
  before_ = R_d;
  slew_[0].setZero();
}

ReferenceSchedule::ReferenceSchedule(std::span<const Waypoint> waypoints,
                                     Interpolation interpolation)
    : interpolation_(interpolation) {
  if (waypoints.empty() || waypoints.size() > static_cast<std::size_t>(kMaxWaypoints)) {
    throw SetupError("reference schedule: needs between 1 and " +
                                std::to_string(kMaxWaypoints) + " waypoints");
  }
  count_ = static_cast<int>(waypoints.size());
  for (int i = 0; i < count_; ++i) {
    const Waypoint& w = waypoints[static_cast<std::size_t>(i)];
    if (!std::isfinite(w.t) || !lie::is_rotation(w.R_d, 1e-6)) {
      throw SetupError("reference schedule: waypoint " + std::to_string(i) +
                                  " has a non-finite time or is not a rotation");
    }
    if (i > 0 && !(w.t > waypoints[static_cast<std::size_t>(i - 1)].t)) {
      throw SetupError("reference schedule: waypoint times must increase strictly");
    }
    waypoints_[static_cast<std::size_t>(i)] = w;
  }
  for (int i = 0; i + 1 < count_; ++i) {
    const auto k = static_cast<std::size_t>(i);
    slew_[k] = lie::log(waypoints_[k].R_d.transpose() * waypoints_[k + 1].R_d);
  }
  before_ = waypoints_[0].R_d;
}

ReferenceSchedule::ReferenceSchedule(std::span<const Waypoint> waypoints,
                                     Interpolation interpolation, const Mat3& R_before)
    : ReferenceSchedule(waypoints, interpolation) {
  if (!lie::is_rotation(R_before, 1e-6)) {
    throw SetupError("reference schedule: the attitude before the first waypoint is not a rotation");
  }
  before_ = R_before;
}

Mat3 ReferenceSchedule::at(double t) const noexcept {
  if (t < waypoints_[0].t) {
    return before_;
  }
  if (count_ == 1 || t <= waypoints_[0].t) {
    return waypoints_[0].R_d;
  }
  // The segment [t_i, t_{i+1}) holding t (linear scan: schedules are short).
  int i = 0;
  while (i + 1 < count_ && t >= waypoints_[static_cast<std::size_t>(i + 1)].t) {
    ++i;
  }
  const auto k = static_cast<std::size_t>(i);
  if (i + 1 == count_ || interpolation_ == Interpolation::hold) {
    return waypoints_[k].R_d;
  }
  const double s = (t - waypoints_[k].t) / (waypoints_[k + 1].t - waypoints_[k].t);
  return waypoints_[k].R_d * lie::exp(s * slew_[k]);
}

}  // namespace attiguard::governor
