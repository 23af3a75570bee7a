#pragma once
/// @file retain_sink.hpp
/// A row sink that keeps the retained columns of one run at t_k = k · interval
/// (docs/campaigns.md, "Retained time series"): the row at t = t_k (to within 10⁻⁹ of the
/// interval) gives sample k. A run whose rows skip a t_k (retain_interval below the row spacing,
/// or no multiple of it) throws InputError "[campaign] retain_interval: no trajectory row at the
/// retained time …", never a sample stamped with a time it does not have.

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "attiguard/campaign/retain_plan.hpp"
#include "attiguard/io/row_sink.hpp"

namespace attiguard::campaign {

class RetainSink final : public io::RowSink {
 public:
  explicit RetainSink(RetainPlan plan) : plan_(std::move(plan)) {}
  /// Finds the retained columns; throws InputError "[campaign] retain: no column 'X' in the
  /// trajectory of this kind (columns: …)" when one is missing.
  void begin(const std::vector<std::string>& columns) override;
  void row(std::span<const double> values) override;
  /// Samples kept.
  [[nodiscard]] std::size_t samples() const noexcept { return times_.size(); }
  /// The kept values, column-major: values()[c * samples() + k].
  [[nodiscard]] std::vector<double> values() const;
  /// The sample times t_k.
  [[nodiscard]] const std::vector<double>& times() const noexcept { return times_; }

 private:
  RetainPlan plan_;
  std::vector<std::size_t> index_;
  std::size_t t_index_{0};
  double previous_t_{0.0};  ///< t of the row before, for the message
  std::vector<double> times_;
  std::vector<std::vector<double>> kept_;  ///< per column
};

}  // namespace attiguard::campaign
