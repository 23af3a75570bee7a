#pragma once
/// @file json_values.hpp
/// Numbers as JSON values, for the JSON a library builds (scenario documents from arguments, the
/// view page's data; docs/conventions.md, "Outputs"): a vector as an array, a matrix as an array
/// of its rows. Templates over the container (std::vector, an Eigen vector or matrix), so that
/// io/ needs no linear-algebra header.

#include <cstddef>
#include <functional>

#include <nlohmann/json.hpp>

namespace attiguard::io {

/// The elements x of `v` (anything a range-for walks: std::vector<double>, an Eigen vector), in
/// order, as a JSON array of map(x) (the number itself by default).
template <class Vector, class Map = std::identity>
[[nodiscard]] nlohmann::json json_array(const Vector& v, Map map = {}) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& x : v) out.push_back(map(x));
  return out;
}

/// The rows of `M` (M.rows(), M.cols(), M(r, c): an Eigen matrix) as a JSON array of row arrays:
/// [[M(0,0), M(0,1), …], [M(1,0), …], …].
template <class Matrix>
[[nodiscard]] nlohmann::json json_rows(const Matrix& M) {
  nlohmann::json rows = nlohmann::json::array();
  for (decltype(M.rows()) r = 0; r < M.rows(); ++r) {
    nlohmann::json row = nlohmann::json::array();
    for (decltype(M.cols()) c = 0; c < M.cols(); ++c) row.push_back(M(r, c));
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace attiguard::io
