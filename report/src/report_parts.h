#pragma once
// Internal to the report: what its sections share (report.cpp, report_plots.cpp, report_crush.cpp).
#include <functional>
#include <string>
#include <vector>

#include "dymesh/analysis/summary.h"

namespace dymesh::report {

/// Everything a section reads: the run, its summary and the output units.
struct Context {
  const Simulation& sim;
  const Summary& summary;
  OutputUnits units;
  double crush_scale = 0.0;  ///< [m] largest permanent crush of the run (colour scale)
};

/// Colour of body i in every plot.
std::string BodyColour(int i);

/// A body name made safe for element ids ("plot-acceleration-" + this).
std::string IdPart(const std::string& name);

/// True when body i moves (its motion is not "fixed").
bool Moves(const Simulation& sim, int i);

/// Sample index nearest to time t.
std::size_t SampleAt(const Simulation& sim, double t);

/// Times of every sample [s], and a per-sample quantity of body i.
std::vector<double> Times(const Simulation& sim);
std::vector<double> BodySeries(const Simulation& sim, int i, const std::function<double(const BodySample&)>& f);

/// A figure: the svg with a caption (HTML-escaped text).
std::string Figure(const std::string& svg, const std::string& caption);

/// Crush colour classes "c0".."c47" as CSS (the crush views use them).
std::string CrushColourCss();
/// Class of a crush fraction of the scale's maximum.
std::string CrushClass(double fraction);

/// Time-history figures: acceleration per moving body, delta-V, force, moment, energy.
std::string TimeHistorySection(const Context& c);
/// Top view of the trajectories with outlines at first contact, maximum engagement and separation.
std::string TrajectorySection(const Context& c);
/// Crush views and the six-point crush of every deformable body.
std::string CrushSection(const Context& c);

}  // namespace dymesh::report
