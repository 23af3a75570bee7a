#include "attiguard/sim/cone_json.hpp"

#include <numbers>

#include "attiguard/io/json_values.hpp"

namespace attiguard::sim {

nlohmann::json cone_json(const governor::ConeConstraint& c) {
  return {{"axis_b", io::json_array(c.axis_b)},
          {"direction_i", io::json_array(c.direction_i)},
          {"theta_c_deg", c.theta_c * 180.0 / std::numbers::pi}};
}

}  // namespace attiguard::sim
