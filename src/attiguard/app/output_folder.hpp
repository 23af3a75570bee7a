#pragma once
/// @file output_folder.hpp
/// The output-folder contract of every command (docs/conventions.md, "Outputs"): a command owns
/// the set of files it writes; before it writes anything it removes every file that any
/// attiguard command could have written in its folder and that it will not write (the fixed
/// names of output_names() over all commands, the figures DIR/plots.txt records, the scratch
/// folder and the replay folders run_K/), each file is written as NAME.partial and renamed when
/// complete, and a command that fails (exit 2 or 3, SIGINT/SIGTERM included) renames the files
/// it completed back to NAME.partial, removes its figures and writes its status file
/// STATUS.partial ({"status": "partial", ...}, io/output_records.hpp). An exit 4 (a verification
/// that failed, a search that found nothing) is a result: its files stay complete.
///
/// `view DIR` and `export-aem DIR` read the results in DIR: they own only the file they write
/// (view.html, attitude.aem), remove that file before reading, and never touch the rest.

#include <exception>
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace attiguard::app {

/// The commands that write into an output folder.
enum class OutputCommand { run, reach, campaign, replay, tune, view, export_aem, plan };

/// The fixed file names `command` may write into its folder (figures, listed in plots.txt, are
/// not fixed names). The one table of output names: every other list derives from it
/// (docs/conventions.md, "Outputs", point 1).
[[nodiscard]] std::span<const std::string> output_names(OutputCommand command);

/// The union of output_names() over every command: what clean-up removes (with NAME.partial;
/// docs/conventions.md, "Outputs", point 1).
[[nodiscard]] std::span<const std::string> known_output_names();

/// The status file of `command` (its STATUS.partial says why it failed): "summary.json" for run
/// and replay, "reach.json", "campaign.json", "tune.json", "plan.json"; "" for view and export-aem
/// (docs/conventions.md, "Outputs", point 3).
[[nodiscard]] std::string status_name(OutputCommand command);

/// What a command keeps of the earlier files in its folder when it claims it (`campaign --resume`:
/// docs/conventions.md, "Outputs", exceptions).
struct Keep {
  std::vector<std::string> names;  ///< fixed output names left in place (inputs it reads)
  bool replays{false};             ///< keep the replay folders run_K/ (campaign --resume)
};

/// One command's output folder (docs/conventions.md, "Outputs").
class OutputFolder {
 public:
  /// `active` false (an MPI rank other than 0): claim() and fail() touch nothing. `inputs`: the
  /// files the command reads (its scenario), never removed nor renamed even when they carry an
  /// output name (`attiguard run` of DIR's resolved scenario into DIR, `tune` of DIR's best point into DIR).
  OutputFolder(std::filesystem::path dir, OutputCommand command, bool active = true,
               const std::vector<std::filesystem::path>& inputs = {});

  /// Removes from the folder, when it exists, every earlier output this command will not keep:
  /// for run, reach, campaign, replay and tune every known name (and NAME.partial) not in
  /// `keep`, the figures of DIR/plots.txt, DIR/.scratch and the replay folders run_K/ (their
  /// known files; the folder when nothing else is left); for view and export-aem only their own
  /// file. Call it before anything is written, before the input is checked (docs/conventions.md,
  /// "Outputs", point 1).
  void claim(const Keep& keep = {});

  /// The scenario kind and file named in the status file (docs/conventions.md, "Outputs", point 3).
  void set_subject(std::string kind, std::string scenario);

  /// Throws io::Interrupted when SIGINT or SIGTERM arrived: call it before reporting success
  /// (docs/conventions.md, "Outputs", point 4).
  void finish() const;

  /// The failure `error` (the exception being handled) leaves the folder: untouched before
  /// claim() (a refused `campaign --resume` changes nothing); an exit 4 leaves its results; otherwise the files of this command that were completed become NAME.partial again
  /// (except the campaign's resume state: runs.csv, campaign_identity.json, retained.h5), its
  /// figures are removed and STATUS.partial says why (with the earlier STATUS file's content
  /// under "result" when there was one, e.g. a mission's summary). Then rethrows it — as
  /// io::Interrupted naming the signal and the folder when a signal arrived meanwhile
  /// (docs/conventions.md, "Outputs", points 3 and 4).
  [[noreturn]] void fail(const std::exception_ptr& error) const;

  /// The folder (docs/conventions.md, "Outputs").
  [[nodiscard]] const std::filesystem::path& dir() const noexcept { return dir_; }

 private:
  std::filesystem::path dir_;
  OutputCommand command_;
  bool active_;
  bool claimed_{false};
  std::vector<std::filesystem::path> inputs_;  ///< weakly canonical
  std::string kind_;
  std::string scenario_;
};

/// Runs one command's `body` inside the output-folder protocol (docs/conventions.md, "Outputs"):
/// claims `folder` first unless `claim_first` is false (`campaign --resume` claims its folder
/// itself once the identity matches), names `scenario` (and `kind`, "" while unknown) in its
/// status file, then runs `body`; an exception from it fails the folder (OutputFolder::fail,
/// which rethrows it).
void run_in_folder(OutputFolder& folder, const std::string& kind,
                   const std::filesystem::path& scenario, const std::function<void()>& body,
                   bool claim_first = true);

}  // namespace attiguard::app
