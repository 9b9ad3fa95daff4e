#pragma once
#include <string>

#include "dymesh/analysis/summary.h"

/// The HTML report of a run: one self-contained file (no scripts, fonts or network) that also
/// parses as XHTML, with inline SVG drawn by the engine: acceleration pulses, delta-V with PDOF,
/// contact force and moment, energies, a top view of the trajectories with body outlines, crush
/// views coloured by permanent crush with the six-point crush C1..C6, and the summary tables.
/// Every figure's <svg> has an id "plot-..." (see README, "Report").
namespace dymesh {

/// The report of a finished (or stopped) run in the scenario's unit system.
std::string ReportHtml(const Simulation& sim, const Summary& summary);

}  // namespace dymesh
