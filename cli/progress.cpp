#include "progress.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace dymesh::cli {
namespace {

// "12 s", "3 min 05 s", "1 h 02 min"
std::string FormatDuration(double seconds) {
  const long s = std::lround(std::max(seconds, 0.0));
  char text[48];
  if (s < 60)
    std::snprintf(text, sizeof text, "%ld s", s);
  else if (s < 3600)
    std::snprintf(text, sizeof text, "%ld min %02ld s", s / 60, s % 60);
  else
    std::snprintf(text, sizeof text, "%ld h %02ld min", s / 3600, (s % 3600) / 60);
  return text;
}

}  // namespace

std::string FormatProgress(double time, double duration, int steps, double elapsed, int bar_width) {
  const double fraction = duration > 0.0 ? std::clamp(time / duration, 0.0, 1.0) : 1.0;
  std::string s;
  // the bar
  if (bar_width > 0) {
    const int filled = static_cast<int>(fraction * bar_width);
    s.append("[").append(filled, '#').append(bar_width - filled, '.').append("] ");
  }
  // percent, simulated time, speed and the time left at this speed
  char text[160];
  const double rate = elapsed > 0.0 ? steps / elapsed : 0.0;
  std::snprintf(text, sizeof text, "%3d%%  t %.4f / %.4f s  %.0f steps/s", static_cast<int>(fraction * 100.0), time,
                duration, rate);
  s += text;
  if (time > 0.0 && elapsed > 0.0) s += "  ETA " + FormatDuration(elapsed * (duration - time) / time);
  return s;
}

double SteadySeconds() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

ProgressReporter::ProgressReporter(std::ostream& out, double duration, Options options, std::function<double()> clock)
    : out_(out), duration_(duration), options_(options), clock_(std::move(clock)) {
  start_ = clock_();
  last_report_ = start_;
}

void ProgressReporter::Update(double time, int steps) {
  // quiet for short runs, then at the redraw (terminal) or line period (log)
  const double now = clock_();
  const double elapsed = now - start_;
  if (elapsed < options_.delay) return;
  const double period = options_.terminal ? options_.redraw_period : options_.line_period;
  if (shown_ && now - last_report_ < period) return;
  last_report_ = now;
  shown_ = true;
  if (options_.terminal)
    out_ << "\r\033[K" << FormatProgress(time, duration_, steps, elapsed, options_.bar_width) << std::flush;
  else
    out_ << "progress: " << FormatProgress(time, duration_, steps, elapsed, 0) << std::endl;
}

void ProgressReporter::Finish() {
  // a terminal bar gives its line back; plain lines stay
  if (shown_ && options_.terminal) out_ << "\r\033[K" << std::flush;
}

}  // namespace dymesh::cli
