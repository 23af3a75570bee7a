#pragma once
// The eight slew problems of the planner's validation (docs/slew-planner.md, "Validation"),
// shared by the planner's validation and the planned mode's flights (docs/pet-erg.md,
// section 16.2): craft from a 3U CubeSat to a 4e6 kg m² station, one to sixteen cones, keep-in
// and keep-out, the Sun on the eigenaxis path, a target near a cone's edge.

#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include "attiguard/governor/cone_constraint.hpp"
#include "attiguard/lie/so3.hpp"
#include "attiguard/plan/slew_problem.hpp"

namespace attiguard::plan::eight_problems {

using governor::keep_in_cone;
using governor::keep_out_cone;
using lie::Mat3;
using lie::Vec3;

inline constexpr double kDeg = std::numbers::pi / 180.0;

struct Case {
  std::string name;
  SlewProblem problem;
};

/// The inertial direction that body axis a_b points to halfway along the eigenaxis path.
inline Vec3 halfway_direction(const SlewProblem& p, const Vec3& axis_b) {
  const Vec3 w = lie::log(p.R_start.transpose() * p.R_target);
  return p.R_start * lie::exp(0.5 * w) * axis_b;
}

inline Case cubesat_sun_on_the_path() {
  Case c{"3U CubeSat, Sun centred on the eigenaxis path", {}};
  SlewProblem& p = c.problem;
  p.J_b = Vec3(0.042, 0.042, 0.007).asDiagonal();
  p.tau_max = 1e-3;
  p.R_target = lie::exp(Vec3(1.0, 0.0, 0.0) * 140.0 * kDeg);
  p.cones.push_back(keep_out_cone(Vec3::UnitZ(), halfway_direction(p, Vec3::UnitZ()), 30.0 * kDeg));
  p.cone_margin = 2.0 * kDeg;
  return c;
}

inline Case station_with_products_of_inertia() {
  Case c{"station 4e6 kg m^2, products of inertia, 2 cones", {}};
  SlewProblem& p = c.problem;
  p.J_b << 4.1e6, 2.0e5, -1.5e5,  //
      2.0e5, 6.3e6, 3.0e5,        //
      -1.5e5, 3.0e5, 8.8e6;
  p.tau_max = 25.0;
  p.R_target = lie::exp(Vec3(0.2, -1.0, 0.4).normalized() * 100.0 * kDeg);
  p.cones.push_back(keep_out_cone(Vec3::UnitX(), halfway_direction(p, Vec3::UnitX()) +
                                                     Vec3(0.0, 0.15, 0.0),
                                  20.0 * kDeg));
  p.cones.push_back(keep_out_cone(-Vec3::UnitZ(), Vec3(0.3, 0.4, 0.85), 15.0 * kDeg));
  p.cone_margin = 1.0 * kDeg;
  return c;
}

inline Case several_cones() {
  Case c{"paper J, 4 keep-out cones on 3 body axes", {}};
  SlewProblem& p = c.problem;
  p.J_b = Vec3(1.0, 2.0, 3.0).asDiagonal();
  p.tau_max = 2.5;
  p.R_target = lie::exp(Vec3(0.5, 1.0, -0.3).normalized() * 160.0 * kDeg);
  p.cones.push_back(keep_out_cone(Vec3::UnitZ(), halfway_direction(p, Vec3::UnitZ()), 25.0 * kDeg));
  p.cones.push_back(keep_out_cone(Vec3::UnitZ(), Vec3(-0.7, 0.7, 0.1), 20.0 * kDeg));
  p.cones.push_back(keep_out_cone(Vec3::UnitX(), Vec3(0.1, -0.2, -0.97), 20.0 * kDeg));
  p.cones.push_back(keep_out_cone(Vec3::UnitY(), Vec3(0.6, 0.6, -0.5), 15.0 * kDeg));
  p.cone_margin = 1.0 * kDeg;
  return c;
}

inline Case keep_in_with_keep_out() {
  Case c{"keep-in antenna 100 deg with a Sun keep-out", {}};
  SlewProblem& p = c.problem;
  p.J_b << 12.0, 0.4, 0.0,  //
      0.4, 15.0, -0.6,      //
      0.0, -0.6, 9.0;
  p.tau_max = 0.2;
  p.R_target = lie::exp(Vec3(0.0, 1.0, 0.3).normalized() * 120.0 * kDeg);
  // The antenna (−z) stays within 100 deg of the ground direction halfway between its ends.
  const Vec3 ground = (p.R_start * -Vec3::UnitZ() + p.R_target * -Vec3::UnitZ()).normalized();
  p.cones.push_back(keep_in_cone(-Vec3::UnitZ(), ground, 100.0 * kDeg));
  p.cones.push_back(keep_out_cone(Vec3::UnitX(), halfway_direction(p, Vec3::UnitX()), 25.0 * kDeg));
  p.cone_margin = 1.0 * kDeg;
  return c;
}

inline Case target_near_a_cone_edge() {
  Case c{"target 1.5 deg outside a keep-out cone's margin", {}};
  SlewProblem& p = c.problem;
  p.J_b = Vec3(3.0, 2.5, 1.2).asDiagonal();
  p.tau_max = 0.5;
  p.R_target = lie::exp(Vec3(1.0, 1.0, 0.0).normalized() * 75.0 * kDeg);
  // The Sun 20 + 1 + 1.5 deg from the target's +z, on the side away from the start.
  const Vec3 z_target = p.R_target * Vec3::UnitZ();
  const Vec3 away = (z_target - Vec3::UnitZ()).normalized();
  const Vec3 tangent = (away - away.dot(z_target) * z_target).normalized();
  const double off = (20.0 + 1.0 + 1.5) * kDeg;
  p.cones.push_back(
      keep_out_cone(Vec3::UnitZ(), std::cos(off) * z_target + std::sin(off) * tangent, 20.0 * kDeg));
  p.cone_margin = 1.0 * kDeg;
  return c;
}

inline Case small_slew_beside_a_cone() {
  Case c{"CubeSat 25 deg slew beside a 40 deg Sun cone", {}};
  SlewProblem& p = c.problem;
  p.J_b << 0.031, 0.001, 0.0,  //
      0.001, 0.029, 0.0005,    //
      0.0, 0.0005, 0.011;
  p.tau_max = 2e-3;
  p.R_target = lie::exp(Vec3(0.0, 1.0, 0.0) * 25.0 * kDeg);
  const Vec3 mid = halfway_direction(p, Vec3::UnitZ());
  p.cones.push_back(keep_out_cone(Vec3::UnitZ(), (mid + 0.9 * Vec3::UnitY()).normalized(), 40.0 * kDeg));
  p.cone_margin = 1.0 * kDeg;
  return c;
}

inline Case near_half_turn_keep_in() {
  Case c{"paper keep-in 160 deg, 175 deg slew", {}};
  SlewProblem& p = c.problem;
  p.J_b = Vec3(1.0, 2.0, 3.0).asDiagonal();
  p.tau_max = 2.5;
  p.R_target = lie::exp(Vec3(0.0, 1.0, 0.0) * 175.0 * kDeg);
  p.cones.push_back(keep_in_cone(Vec3::UnitZ(), Vec3(-0.791, 0.061, -0.609), 160.0 * kDeg));
  p.cone_margin = 0.5 * kDeg;
  return c;
}

inline Case sixteen_cones() {
  Case c{"16 keep-out cones of 8 deg on +z and +x", {}};
  SlewProblem& p = c.problem;
  p.J_b << 2.4, 0.12, -0.08,  //
      0.12, 3.1, 0.05,        //
      -0.08, 0.05, 3.9;
  p.tau_max = 0.05;
  p.R_target = lie::exp(Vec3(0.3, 1.0, 0.2).normalized() * 150.0 * kDeg);
  std::uint64_t state = 0x2545f4914f6cdd1dULL;
  const auto uniform = [&state] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) * 0x1.0p-53 * 2.0 - 1.0;
  };
  const double alpha = 8.0 * kDeg;
  while (p.cones.size() < 16) {
    const Vec3 axis_b = p.cones.size() % 2 == 0 ? Vec3::UnitZ() : Vec3::UnitX();
    const Vec3 s(uniform(), uniform(), uniform());
    if (s.norm() < 0.2 || s.norm() > 1.0) continue;
    const Vec3 avoid_i = s.normalized();
    const double clear = alpha + 5.0 * kDeg;
    if (std::acos(avoid_i.dot(p.R_start * axis_b)) < clear ||
        std::acos(avoid_i.dot(p.R_target * axis_b)) < clear)
      continue;
    p.cones.push_back(keep_out_cone(axis_b, avoid_i, alpha));
  }
  p.cone_margin = 0.5 * kDeg;
  return c;
}

inline std::vector<Case> cases() {
  return {cubesat_sun_on_the_path(), station_with_products_of_inertia(), several_cones(),
          keep_in_with_keep_out(),   target_near_a_cone_edge(),          small_slew_beside_a_cone(),
          near_half_turn_keep_in(),  sixteen_cones()};
}

}  // namespace attiguard::plan::eight_problems
