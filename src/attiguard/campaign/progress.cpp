#include "attiguard/campaign/progress.hpp"

#include <cstdio>
#include <ostream>
#include <string>

namespace attiguard::campaign {

namespace {
std::string eta_text(double seconds) {
  char buf[32];
  const long s = static_cast<long>(seconds + 0.5);
  if (s >= 3600) {
    std::snprintf(buf, sizeof buf, "%ldh%02ldm", s / 3600, (s / 60) % 60);
  } else {
    std::snprintf(buf, sizeof buf, "%ldm%02lds", s / 60, s % 60);
  }
  return buf;
}
}  // namespace

Progress::Progress(std::ostream& out, long total, bool tty)
    : out_(out), total_(total), tty_(tty), start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

void Progress::tick() {
  ++done_;
  draw();
}

void Progress::draw() {
  if (total_ <= 0) return;
  const auto now = std::chrono::steady_clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double eta = done_ > 0 ? elapsed * static_cast<double>(total_ - done_) / static_cast<double>(done_) : 0.0;
  const double frac = static_cast<double>(done_) / static_cast<double>(total_);
  if (tty_) {
    if (done_ != total_ && now - last_draw_ < std::chrono::milliseconds(100)) return;
    last_draw_ = now;
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(frac * kWidth);
    out_ << "\r[" << std::string(static_cast<std::size_t>(filled), '#')
         << std::string(static_cast<std::size_t>(kWidth - filled), ' ') << "] " << done_ << "/"
         << total_ << " ETA " << eta_text(eta) << "   " << std::flush;
    return;
  }
  const int decile = static_cast<int>(frac * 10.0);
  if (decile == last_decile_) return;
  last_decile_ = decile;
  out_ << "campaign: " << done_ << "/" << total_ << " runs (" << static_cast<int>(frac * 100.0)
       << " %), elapsed " << eta_text(elapsed) << ", ETA " << eta_text(eta) << '\n'
       << std::flush;
}

void Progress::finish() {
  if (tty_ && total_ > 0) out_ << '\n' << std::flush;
}

}  // namespace attiguard::campaign
