#pragma once
/// @file campaign_command.hpp
/// `attiguard campaign SCENARIO --runs N --seed S --out DIR [--threads T] [--replay K]
/// [--resume] [--plot]` (docs/campaigns.md).

#include <cstdint>
#include <filesystem>
#include <optional>

namespace attiguard::cli {

/// Arguments of `attiguard campaign`.
struct CampaignArguments {
  std::filesystem::path scenario;
  std::filesystem::path out_dir;
  long runs{0};
  std::uint64_t seed{1};
  int threads{1};
  std::optional<long> replay;
  bool resume{false};
  bool plot{false};
  bool view{false};  ///< --view (with --replay): DIR/run_K/view.html (docs/viewer.md)
  bool aem{false};   ///< --aem (with --replay): DIR/run_K/attitude.aem (docs/interop.md)
};

/// Runs the campaign (or replays one run); see docs/campaigns.md for the outputs.
void campaign_command(const CampaignArguments& args);

}  // namespace attiguard::cli
