#pragma once
#include <string>
#include <vector>

#include "dymesh/ensemble/sample_run.h"
#include "dymesh/ensemble/spec.h"

/// report.html of an ensemble: one self-contained page (inline SVG, no scripts), valid XHTML.
namespace dymesh::ensemble {

/// Per output a histogram and a CDF with the statistics; a tornado of rank correlations; scatter
/// plots of each input against the first body's delta-V; delta-V against PDOF; convergence of the
/// mean and P5/P95; the samples not in the statistics (with why); the spec, seed, hash and version.
std::string EnsembleReportHtml(const Spec& spec, const std::vector<SampleRecord>& records);

}  // namespace dymesh::ensemble
