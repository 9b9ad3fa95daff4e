#pragma once
#include <string>
#include <vector>

#include "dymesh/ensemble/sample_run.h"
#include "dymesh/ensemble/spec.h"

/// report.html of an ensemble: one self-contained page (inline SVG, no scripts), valid XHTML.
namespace dymesh::ensemble {

/// The statistics of `ensemble_json` (ensemble.json's text, so the page shows the file's numbers) with their
/// bootstrap intervals, the exceedance probabilities and the posterior; per output a histogram and a CDF,
/// convergence of the mean and P5/P95, Sobol' bars (Saltelli design); for delta-V a tornado of rank
/// correlations, scatter plots of each input and delta-V against PDOF; the samples not in the statistics
/// (with why); the spec, seed, hash and version.
std::string EnsembleReportHtml(const Spec& spec, const std::vector<SampleRecord>& records, const std::string& ensemble_json);

}  // namespace dymesh::ensemble
