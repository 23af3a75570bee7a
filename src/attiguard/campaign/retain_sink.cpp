#include "attiguard/campaign/retain_sink.hpp"

#include <cstdio>

#include "attiguard/core/errors.hpp"

namespace attiguard::campaign {

void RetainSink::begin(const std::vector<std::string>& columns) {
  index_.clear();
  kept_.assign(plan_.columns.size(), {});
  times_.clear();
  previous_t_ = 0.0;
  bool have_t = false;
  for (std::size_t i = 0; i < columns.size(); ++i) {
    if (columns[i] == "t") {
      t_index_ = i;
      have_t = true;
    }
  }
  for (const std::string& name : plan_.columns) {
    std::size_t found = columns.size();
    for (std::size_t i = 0; i < columns.size(); ++i) {
      if (columns[i] == name) found = i;
    }
    if (found == columns.size() || !have_t) {
      std::string list;
      for (const auto& c : columns) list += (list.empty() ? "" : ", ") + c;
      throw InputError("[campaign] retain: no column '" + name +
                       "' in the trajectory of this kind (columns: " + list + ")");
    }
    index_.push_back(found);
  }
}

void RetainSink::row(std::span<const double> values) {
  const double t = values[t_index_];
  const double next = static_cast<double>(times_.size()) * plan_.interval;
  const double tolerance = 1e-9 * plan_.interval;
  if (t < next - tolerance) {
    previous_t_ = t;
    return;
  }
  if (t > next + tolerance) {
    // No row at t_k: its value would be stamped with a time it does not have.
    char text[320];
    std::snprintf(text, sizeof text,
                  "[campaign] retain_interval: no trajectory row at the retained time t = %.9g s "
                  "(the rows around it are at t = %.9g s and %.9g s): retain_interval = %.9g s "
                  "must be a multiple of the spacing of the trajectory's rows (output_interval)",
                  next, previous_t_, t, plan_.interval);
    throw InputError(text);
  }
  previous_t_ = t;
  times_.push_back(next);
  for (std::size_t c = 0; c < index_.size(); ++c) kept_[c].push_back(values[index_[c]]);
}

std::vector<double> RetainSink::values() const {
  std::vector<double> out;
  out.reserve(kept_.size() * times_.size());
  for (const auto& column : kept_) out.insert(out.end(), column.begin(), column.end());
  return out;
}

}  // namespace attiguard::campaign
