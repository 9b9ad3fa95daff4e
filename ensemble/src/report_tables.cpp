#include "report_tables.h"

#include "dymesh/report/svg_plot.h"

namespace dymesh::ensemble {
namespace {

// a cell ensemble.json has no number for
constexpr const char* kNoValue = "<td>&#8211;</td>";

// a table cell of a number (3 decimals), or a dash when ensemble.json has none
std::string Cell(const nlohmann::json& value) {
  return value.is_number() ? "<td>" + FormatFixed(value.get<double>(), 3) + "</td>" : kNoValue;
}

// a cell of an interval [low, high]
std::string IntervalCell(const nlohmann::json& interval) {
  if (!interval.is_array() || interval.size() != 2 || !interval[0].is_number() || !interval[1].is_number())
    return kNoValue;
  return "<td>" + FormatFixed(interval[0].get<double>(), 3) + " .. " + FormatFixed(interval[1].get<double>(), 3) + "</td>";
}

// the cells of mean, SD, P5, P50, P95 of one summary (an ensemble.json object, or null)
std::string SummaryCells(const nlohmann::json& s) {
  std::string cells;
  for (const char* key : {"mean", "sd", "p5", "p50", "p95"}) cells += Cell(s.is_object() && s.contains(key) ? s[key] : nullptr);
  return cells;
}

// one row per quantity of a group (inputs or outputs): its prior and posterior summaries side by side
std::string PriorPosteriorRows(const nlohmann::json& prior, const nlohmann::json& posterior) {
  std::string rows;
  for (const auto& [name, post] : posterior.items())
    rows += "<tr><td>" + XmlEscape(name) + "</td>" + SummaryCells(prior.contains(name) ? prior[name] : nullptr) +
            SummaryCells(post) + "</tr>\n";
  return rows;
}

}  // namespace

std::string StatisticsTable(const nlohmann::json& outputs) {
  std::string t = "<table id=\"table-statistics\"><thead><tr><th>output</th><th>n</th><th>mean</th><th>SD</th><th>P5</th>"
                  "<th>P50</th><th>P95</th><th>min</th><th>max</th><th>mean 95 % CI</th><th>P5 95 % CI</th>"
                  "<th>P95 95 % CI</th></tr></thead><tbody>\n";
  for (const auto& [name, o] : outputs.items()) {
    t += "<tr><td>" + XmlEscape(name) + "</td><td>" + std::to_string(o.value("n", 0)) + "</td>";
    for (const char* key : {"mean", "sd", "p5", "p50", "p95", "min", "max"}) t += Cell(o.contains(key) ? o[key] : nullptr);
    const nlohmann::json ci = o.value("ci95", nlohmann::json::object());
    for (const char* key : {"mean", "p5", "p95"}) t += IntervalCell(ci.contains(key) ? ci[key] : nullptr);
    t += "</tr>\n";
  }
  return t + "</tbody></table>\n<p class=\"note\">95 % confidence intervals by bootstrap over the samples in the "
             "statistics (seeded from the spec: the same every run).</p>\n";
}

std::string ExceedanceTable(const nlohmann::json& exceedance) {
  if (!exceedance.is_array() || exceedance.empty()) return "";
  std::string t = "<h2 id=\"exceedance\">Exceedance</h2>\n<table id=\"table-exceedance\"><thead><tr><th>output</th>"
                  "<th>threshold</th><th>samples</th><th>P(output &gt; threshold)</th></tr></thead><tbody>\n";
  for (const nlohmann::json& e : exceedance)
    t += "<tr><td>" + XmlEscape(e.value("output", "")) + "</td>" + Cell(e["above"]) + "<td>" +
         std::to_string(e.value("n", 0)) + "</td>" + Cell(e["probability"]) + "</tr>\n";
  return t + "</tbody></table>\n";
}

std::string PosteriorSection(const nlohmann::json& statistics) {
  if (!statistics.contains("posterior")) return "";
  const nlohmann::json& post = statistics["posterior"];
  std::string s = "<h2 id=\"posterior\">Posterior (weighted by the evidence)</h2>\n<p>Evidence: ";
  for (const nlohmann::json& e : post.value("evidence", nlohmann::json::array()))
    s += XmlEscape(e.value("observable", "")) + " = " + FormatFixed(e.value("value", 0.0), 3) + " &#177; " +
         FormatFixed(e.value("sd", 0.0), 3) + " (SD); ";
  s += "effective sample size " + FormatFixed(post.value("effective_sample_size", 0.0), 1) + ".</p>\n";
  if (post.contains("warning"))
    s += "<p class=\"warning\" id=\"posterior-warning\">warning: " + XmlEscape(post["warning"].get<std::string>()) + "</p>\n";
  const nlohmann::json prior = post.value("prior", nlohmann::json::object());
  s += "<table id=\"table-posterior\"><thead><tr><th>quantity</th><th>prior mean</th><th>prior SD</th><th>prior P5</th>"
       "<th>prior P50</th><th>prior P95</th><th>posterior mean</th><th>posterior SD</th><th>posterior P5</th>"
       "<th>posterior P50</th><th>posterior P95</th></tr></thead><tbody>\n";
  for (const char* group : {"inputs", "outputs"})
    s += PriorPosteriorRows(prior.value(group, nlohmann::json::object()), post.value(group, nlohmann::json::object()));
  return s + "</tbody></table>\n<p class=\"note\">Each sample in the statistics weighed by the likelihood of the "
             "evidence (normal, the given SD); the prior columns weigh every such sample alike. SD over the weights "
             "(no n - 1), percentiles the first sample whose cumulative weight reaches them.</p>\n";
}

}  // namespace dymesh::ensemble
