#pragma once
#include <nlohmann/json.hpp>

#include <string>

/// The tables of an ensemble's report.html, read from its ensemble.json (so the page shows the file's numbers).
namespace dymesh::ensemble {

/// Per output: n, mean, SD, P5, P50, P95, min, max, and the bootstrap 95 % intervals of the mean, P5 and P95.
std::string StatisticsTable(const nlohmann::json& outputs);

/// P(output > threshold) for each of the spec's thresholds; empty without thresholds.
std::string ExceedanceTable(const nlohmann::json& exceedance);

/// The evidence, the effective sample size (and its warning), and every input's and output's prior and
/// posterior mean, SD, P5, P50 and P95; empty without evidence.
std::string PosteriorSection(const nlohmann::json& statistics);

}  // namespace dymesh::ensemble
