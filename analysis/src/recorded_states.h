#pragma once
#include <algorithm>
#include <vector>

#include "dymesh/core/simulation.h"

/// The recorded states a measure of how far bodies went into each other looks at (analysis only).
namespace dymesh {

/// At most kRecordedStates recorded states from history index `first` on, evenly spaced, and the last.
inline constexpr std::size_t kRecordedStates = 256;
inline std::vector<const Sample*> EvenlySpacedStates(const Simulation& sim, std::size_t first) {
  std::vector<const Sample*> states;
  const std::vector<Sample>& history = sim.history();
  if (first >= history.size()) return states;
  const std::size_t stride = std::max<std::size_t>(1, (history.size() - first) / kRecordedStates);
  for (std::size_t i = first; i < history.size(); i += stride) states.push_back(&history[i]);
  if (states.back() != &history.back()) states.push_back(&history.back());
  return states;
}

/// The same from the first contact on (none without contact): bodies that went in between the nodes
/// may have come out the far side by the end.
inline std::vector<const Sample*> StatesFromFirstContact(const Simulation& sim) {
  const std::vector<Sample>& history = sim.history();
  if (sim.first_contact_time() < 0.0 || history.empty()) return {};
  const double slack = 0.5 * sim.scenario().time_step;  // the recorded times' round-off
  std::size_t first = 0;
  while (first + 1 < history.size() && history[first].time < sim.first_contact_time() - slack) ++first;
  return EvenlySpacedStates(sim, first);
}

}  // namespace dymesh
