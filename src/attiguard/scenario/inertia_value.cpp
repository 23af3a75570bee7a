// TableReader::inertia: an inertia matrix given as principal moments or as a 3×3 matrix,
// validated with dynamics::inertia_error (docs/scenario-format.md, "Inertia").


#include "attiguard/dynamics/rigid_body.hpp"
#include "attiguard/lie/symmetric_eigen.hpp"
#include "attiguard/scenario/messages.hpp"
#include "attiguard/scenario/table_reader.hpp"

namespace attiguard::scenario {

namespace {
/// The usable range of inertia entries and principal moments [kg m^2].
constexpr double kMaxInertia = 1e12;
constexpr double kMinInertia = 1e-12;
}  // namespace

Eigen::Matrix3d TableReader::inertia(std::string_view key) const {
  static const std::string what =
      "an inertia matrix [kg m^2]: principal moments [J1, J2, J3] or 3 rows of 3 numbers";
  const toml::node* n = take(key);
  if (n == nullptr) {
    missing(key, what);
  }
  const toml::array* a = n->as_array();
  if (a == nullptr || a->empty()) {
    fail(key, "expected " + what + ", got " + detail::describe(*n));
  }
  // A first element that is an array selects the matrix form; anything else the moments form,
  // whose element checks then report what is wrong.
  const Eigen::Matrix3d J =
      a->get(0)->is_array() ? matrix3(key) : Eigen::Matrix3d(vector3(key).asDiagonal());
  // Beyond any body (from 1e-12 to 1e12 kg m^2) a moment is a unit mistake, and near 1e154 its
  // square, formed by the dynamics, overflows: refused as input before it reaches them.
  const double largest = J.cwiseAbs().maxCoeff();
  if (largest > kMaxInertia) {
    fail(key, "an entry of " + detail::format_number(largest) + " kg m^2 is beyond the usable range "
              "of inertias (at most 1e+12 kg m^2; is the unit kg m^2?)");
  }
  if (const auto error = dynamics::inertia_error(J)) {
    fail(key, *error);
  }
  const double smallest = lie::lambda_min(J);
  if (smallest < kMinInertia) {
    fail(key, "a principal moment of " + detail::format_number(smallest) + " kg m^2 is below the "
              "usable range of inertias (at least 1e-12 kg m^2; is the unit kg m^2?)");
  }
  return 0.5 * (J + J.transpose());
}

}  // namespace attiguard::scenario
