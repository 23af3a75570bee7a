#pragma once
/// @file progress.hpp
/// Progress of a campaign on stdout: a bar with ETA redrawn in place on a terminal, plain lines
/// (every 10 % at most) otherwise.

#include <chrono>
#include <iosfwd>

namespace attiguard::campaign {

class Progress {
 public:
  /// `total` runs to do in this invocation; `tty` chooses the bar.
  Progress(std::ostream& out, long total, bool tty);
  /// One more run finished.
  void tick();
  /// Ends the bar (newline on a terminal).
  void finish();

 private:
  void draw();
  std::ostream& out_;
  long total_;
  long done_{0};
  bool tty_;
  int last_decile_{-1};
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
};

}  // namespace attiguard::campaign
