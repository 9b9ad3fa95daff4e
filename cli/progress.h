#pragma once
#include <functional>
#include <ostream>
#include <string>

/// Progress of a run for the dymesh command: a bar redrawn in place on a terminal, a plain line
/// every few seconds otherwise, nothing at all for runs shorter than about two seconds.
namespace dymesh::cli {

/// One progress text: "[#####.....]  45%  t 0.1125 / 0.2500 s  1234 steps/s  ETA 3 s"
/// (no bar when `bar_width` is 0). `elapsed` is wall time [s].
std::string FormatProgress(double time, double duration, int steps, double elapsed, int bar_width);

/// Seconds on a monotonic clock.
double SteadySeconds();

/// Reports a run's progress to `out`; wall time comes from `clock` (seconds, monotonic).
class ProgressReporter {
 public:
  struct Options {
    bool terminal = false;       ///< redraw a bar in place (else plain periodic lines)
    double delay = 2.0;          ///< [s] wall time before the first report
    double line_period = 5.0;    ///< [s] between plain lines
    double redraw_period = 0.1;  ///< [s] between bar redraws
    int bar_width = 30;
  };

  ProgressReporter(std::ostream& out, double duration, Options options, std::function<double()> clock = SteadySeconds);

  /// Called after each step with the simulated time [s] and the steps done.
  void Update(double time, int steps);

  /// Ends the display: clears the bar's line on a terminal.
  void Finish();

 private:
  std::ostream& out_;
  double duration_;
  Options options_;
  std::function<double()> clock_;
  double start_, last_report_;
  bool shown_ = false;
};

}  // namespace dymesh::cli
