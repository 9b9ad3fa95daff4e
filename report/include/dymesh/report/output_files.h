#pragma once
#include <functional>
#include <string>
#include <vector>

#include "dymesh/analysis/summary.h"

/// The files of a run in its output folder: meshes, history, report and summary.
namespace dymesh {

/// The plain names of the files WriteOutputs writes for `scenario`, in writing order: per body
/// NAME_undeformed.obj/.ply and NAME_deformed.obj/.ply, then history.csv, report.html, summary.json.
std::vector<std::string> OutputFileNames(const Scenario& scenario);

/// Which output files were written and which were not (when writing was stopped).
struct WrittenOutputs {
  std::vector<std::string> written, not_written;  ///< paths
};

/// Writes into `dir`: each body's deformed and undeformed mesh (OBJ, and PLY with the permanent
/// crush per vertex), history.csv, report.html and, last, summary.json; each through a temporary
/// name renamed into place. An earlier summary.json is removed first, so its presence always means
/// that the files beside it belong to it. `stop`, when given, is asked before each file: once it
/// returns true the remaining files are skipped (listed in `not_written`).
WrittenOutputs WriteOutputs(const Simulation& sim, const Summary& summary, const std::string& dir,
                            const std::function<bool()>& stop = {});

}  // namespace dymesh
