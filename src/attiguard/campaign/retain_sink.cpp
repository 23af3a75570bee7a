#include "attiguard/campaign/retain_sink.hpp"

#include "attiguard/core/errors.hpp"

namespace attiguard::campaign {

void RetainSink::begin(const std::vector<std::string>& columns) {
  index_.clear();
  kept_.assign(plan_.columns.size(), {});
  times_.clear();
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
  if (t < next - 1e-9 * plan_.interval) return;
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
