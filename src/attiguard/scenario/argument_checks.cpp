// Library arguments validated by the scenario readers (docs/python.md, "Validation").

#include "attiguard/scenario/argument_checks.hpp"

#include <utility>
#include <vector>

#include "attiguard/core/errors.hpp"
#include "attiguard/io/json_values.hpp"
#include "attiguard/scenario/common_tables.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/table_reader.hpp"

namespace attiguard::scenario {

namespace {

/// Replaces every `from` in `m` by `to`.
std::string replaced(std::string m, const std::string& from, const std::string& to) {
  for (auto at = m.find(from); at != std::string::npos; at = m.find(from, at + to.size())) {
    m.replace(at, from.size(), to);
  }
  return m;
}

/// Reads `key` = { `form` } with the file reader's rotation check; the message names the
/// argument itself ("q: …", not "q.quaternion: …"; `renames` maps further key paths).
lie::Mat3 read_rotation_form(const nlohmann::json& form, const std::string& key, const std::string& label,
                             const std::vector<std::pair<std::string, std::string>>& renames) {
  const Document doc = document_from_json({{key, form}}, label);
  try {
    return TableReader(doc).rotation(key);
  } catch (const InputError& e) {
    std::string m = e.what();
    for (const auto& [from, to] : renames) {
      m = replaced(replaced(m, ": " + from + ":", ": " + to + ":"), ": " + from + "[", ": " + to + "[");
    }
    throw InputError(m);
  }
}

}  // namespace

governor::ConeConstraint checked_cone(const nlohmann::json& cone, const std::string& label) {
  const Document doc = document_from_json({{"cone", cone}}, label);
  const TableReader root(doc);
  const TableReader t = root.table("cone");
  const governor::ConeConstraint c = parse_cone(t);
  t.finish();
  return c;
}

governor::GovernorParams checked_governor_params(const nlohmann::json& args, const std::string& label) {
  const Document doc = document_from_json(args, label);
  const TableReader root(doc);
  declare(root, {"governor", "control", "erg", "inertia"});
  governor::GovernorParams params;
  params.J = root.inertia("inertia");
  (void)parse_governor_block(root, params);
  root.finish();
  return params;
}

governor::AttitudeGovernor checked_governor(const governor::GovernorParams& params,
                                            const std::vector<governor::ConeConstraint>& cones,
                                            const std::string& label) {
  const Document doc = document_from_json(nlohmann::json::object(), label);
  return make_governor(TableReader(doc), "", params, cones);
}

lie::Mat3 checked_rotation_matrix(const lie::Mat3& R, const std::string& key, const std::string& label) {
  const Document doc = document_from_json({{key, {{"matrix", io::json_rows(R)}}}}, label);
  try {
    return TableReader(doc).rotation(key);
  } catch (const InputError& e) {  // the argument is the matrix itself: "R: …", not "R.matrix: …"
    std::string m = e.what();
    const std::string form = ": " + key + ".matrix:";
    if (const auto at = m.find(form); at != std::string::npos) m.replace(at, form.size(), ": " + key + ":");
    throw InputError(m);
  }
}

lie::Quat checked_unit_quaternion(const lie::Quat& q, const std::string& key, const std::string& label) {
  (void)read_rotation_form({{"quaternion", {q(0), q(1), q(2), q(3)}}}, key, label,
                           {{key + ".quaternion", key}});
  return q;
}

lie::Vec3 checked_rotation_vector(const lie::Vec3& w, const std::string& key, const std::string& label) {
  (void)read_rotation_form({{"rotation_vector", io::json_array(w)}}, key, label,
                           {{key + ".rotation_vector", key}});
  return w;
}

lie::Vec3 checked_axis_angle(const lie::Vec3& axis, double angle, const std::string& axis_key,
                             const std::string& angle_key, const std::string& label) {
  const std::string key = "axis_angle";
  (void)read_rotation_form({{"axis", io::json_array(axis)}, {"angle", angle}}, key, label,
                           {{key + ".axis", axis_key}, {key + ".angle", angle_key}});
  // The unit axis as the reader scales it (also for an axis whose norm underflows).
  const Document doc = document_from_json({{axis_key, io::json_array(axis)}}, label);
  return TableReader(doc).direction(axis_key);
}

lie::Mat3 checked_matrix3(const lie::Mat3& M, const std::string& key, const std::string& label) {
  const Document doc = document_from_json({{key, io::json_rows(M)}}, label);
  return TableReader(doc).matrix3(key);
}

lie::Vec3 checked_vector3(const lie::Vec3& v, const std::string& key, const std::string& label) {
  const Document doc = document_from_json({{key, io::json_array(v)}}, label);
  return TableReader(doc).vector3(key);
}

double checked_number(double x, const std::string& key, bool positive, const std::string& label) {
  const Document doc = document_from_json({{key, x}}, label);
  return TableReader(doc).number(key, positive ? NumberRule::positive() : NumberRule::non_negative());
}

}  // namespace attiguard::scenario
