#pragma once
#include <string>

#include "dymesh/analysis/summary.h"

/// summary.json: the summary as JSON text in the scenario's unit system (docs/summary.schema.json).
namespace dymesh {

/// The summary as JSON text (indented by 2), with the scenario it came from and the files of the
/// run (`files`, plain names; empty when the summary is not written beside outputs). Values that
/// overflowed in a failed run are written as the largest finite numbers, never null.
std::string SummaryJson(const Summary& summary, const Scenario& scenario, const std::vector<std::string>& files);

}  // namespace dymesh
