// TableReader::inertia: an inertia matrix given as principal moments or as a 3×3 matrix,
// validated with dynamics::inertia_error (docs/scenario-format.md, "Inertia").

#include "attiguard/dynamics/rigid_body.hpp"
#include "attiguard/scenario/messages.hpp"
#include "attiguard/scenario/table_reader.hpp"

namespace attiguard::scenario {

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
  if (const auto error = dynamics::inertia_error(J)) {
    fail(key, *error);
  }
  return 0.5 * (J + J.transpose());
}

}  // namespace attiguard::scenario
