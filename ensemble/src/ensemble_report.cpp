#include "dymesh/ensemble/ensemble_report.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <map>

#include "dymesh/ensemble/statistics.h"
#include "dymesh/report/svg_plot.h"
#include "report_tables.h"

namespace dymesh::ensemble {
namespace {

constexpr const char* kCss = R"(
body { font-family: sans-serif; margin: 16px; color: #222222; }
table { border-collapse: collapse; margin: 8px 0 16px; font-size: 13px; }
th, td { border-bottom: 1px solid #dddddd; padding: 3px 8px; text-align: right; white-space: nowrap; }
th:first-child, td:first-child { text-align: left; }
.figures { display: flex; flex-wrap: wrap; gap: 18px; }
.note { font-size: 12px; color: #555555; max-width: 900px; }
.warning { color: #b00000; font-weight: bold; max-width: 900px; }
svg.plot { border: 1px solid #e6e6e6; }
)";

// an output's values and the samples' inputs, over the samples in the statistics in index order
struct Column {
  std::vector<double> values;
  std::vector<std::vector<double>> inputs;
};

std::map<std::string, Column> Columns(const std::vector<SampleRecord>& records) {
  std::map<std::string, Column> columns;
  for (const SampleRecord& r : records)
    for (const auto& [name, v] : r.outputs) {
      columns[name].values.push_back(v);
      columns[name].inputs.push_back(r.inputs);
    }
  return columns;
}

std::string Id(const std::string& name) {
  std::string id;
  for (char ch : name) id += std::isalnum(static_cast<unsigned char>(ch)) ? ch : '-';
  return id;
}

// histogram (as a step line, 20 bins) and empirical CDF of one output
std::string Distributions(const std::string& name, std::vector<double> v) {
  std::sort(v.begin(), v.end());
  LinePlot cdf{"plot-cdf-" + Id(name), name + ": cumulative distribution", name, "P(X <= x)"};
  PlotSeries c{"empirical CDF"};
  for (std::size_t i = 0; i < v.size(); ++i) c.x.push_back(v[i]), c.y.push_back((i + 1.0) / v.size());
  cdf.series.push_back(c);
  LinePlot hist{"plot-histogram-" + Id(name), name + ": histogram", name, "samples"};
  PlotSeries h{"samples per bin", {}, {}, "#d62728"};
  const int bins = 20;
  const double lo = v.front(), width = std::max(v.back() - lo, 1e-12) / bins;
  std::vector<int> count(bins, 0);
  for (double x : v) ++count[std::min(bins - 1, static_cast<int>((x - lo) / width))];
  for (int b = 0; b < bins; ++b) {
    h.x.push_back(lo + b * width), h.y.push_back(count[b]);
    h.x.push_back(lo + (b + 1) * width), h.y.push_back(count[b]);
  }
  hist.series.push_back(h);
  return RenderLinePlot(hist) + RenderLinePlot(cdf);
}

// horizontal bars of the inputs' rank correlation with one output, largest first
std::string Tornado(const Spec& spec, const std::string& name, const Column& column) {
  std::vector<std::pair<double, std::string>> bars;
  for (std::size_t k = 0; k < spec.inputs.size(); ++k) {
    std::vector<double> x;
    for (const auto& row : column.inputs) x.push_back(row[k]);
    bars.push_back({Spearman(x, column.values), spec.inputs[k].name});
  }
  std::stable_sort(bars.begin(), bars.end(), [](const auto& a, const auto& b) { return std::abs(a.first) > std::abs(b.first); });
  const int row = 22, left = 170, half = 180, height = 40 + row * static_cast<int>(bars.size());
  std::string s = "<svg class=\"plot\" id=\"plot-tornado-" + Id(name) + "\" xmlns=\"http://www.w3.org/2000/svg\" width=\"" +
                  std::to_string(left + 2 * half + 20) + "\" height=\"" + std::to_string(height) + "\">\n";
  s += "<text x=\"8\" y=\"18\" font-size=\"13\">" + XmlEscape(name) + ": Spearman rank correlation of each input</text>\n";
  s += "<line x1=\"" + std::to_string(left + half) + "\" y1=\"28\" x2=\"" + std::to_string(left + half) + "\" y2=\"" +
       std::to_string(height - 6) + "\" stroke=\"#888888\"/>\n";
  for (std::size_t i = 0; i < bars.size(); ++i) {
    const double w = bars[i].first * half;
    const int y = 32 + row * static_cast<int>(i);
    s += "<text x=\"8\" y=\"" + std::to_string(y + 13) + "\" font-size=\"12\">" + XmlEscape(bars[i].second) + "</text>\n";
    s += "<rect x=\"" + FormatFixed(left + half + std::min(0.0, w), 1) + "\" y=\"" + std::to_string(y) + "\" width=\"" +
         FormatFixed(std::abs(w), 1) + "\" height=\"16\" fill=\"" + (w >= 0 ? "#1f77b4" : "#d62728") + "\"/>\n";
    s += "<text x=\"" + std::to_string(left + 2 * half + 2) + "\" y=\"" + std::to_string(y + 13) + "\" font-size=\"11\" text-anchor=\"end\">" +
         FormatFixed(bars[i].first, 2) + "</text>\n";
  }
  return s + "</svg>\n";
}

// a bar's x in a plot of indices over [0, top] drawn `width` wide from `left` (negative estimates at 0)
double IndexX(double value, double top, int left, int width) { return left + std::clamp(value / top, 0.0, 1.0) * width; }

// a number of ensemble.json, 0 where it holds none (an index of an output that never varied is null)
double NumberOr0(const nlohmann::json& j) { return j.is_number() ? j.get<double>() : 0.0; }

// Sobol' first-order and total index bars of each input with their bootstrap 95 % intervals (whiskers)
std::string SobolBars(const std::string& name, const nlohmann::json& sobol) {
  double top = 1.0;
  for (const auto& [input, s] : sobol.items())
    for (const char* key : {"first_ci95", "total_ci95"}) top = std::max(top, NumberOr0(s[key][1]));
  const int row = 40, left = 170, width = 360, height = 52 + row * static_cast<int>(sobol.size());
  std::string s = "<svg class=\"plot\" id=\"plot-sobol-" + Id(name) + "\" xmlns=\"http://www.w3.org/2000/svg\" width=\"" +
                  std::to_string(left + width + 60) + "\" height=\"" + std::to_string(height) + "\">\n";
  s += "<text x=\"8\" y=\"18\" font-size=\"13\">" + XmlEscape(name) +
       ": Sobol' indices, first order (blue) and total (orange), 95 % intervals</text>\n";
  s += "<line x1=\"" + std::to_string(left) + "\" y1=\"28\" x2=\"" + std::to_string(left) + "\" y2=\"" +
       std::to_string(height - 20) + "\" stroke=\"#888888\"/>\n";
  s += "<text x=\"" + FormatFixed(IndexX(1.0, top, left, width), 1) + "\" y=\"" + std::to_string(height - 6) +
       "\" font-size=\"11\" text-anchor=\"middle\">1</text>\n";
  int i = 0;
  for (const auto& [input, index] : sobol.items()) {
    const int y = 32 + row * i++;
    s += "<text x=\"8\" y=\"" + std::to_string(y + 20) + "\" font-size=\"12\">" + XmlEscape(input) + "</text>\n";
    int k = 0;
    for (const auto& [key, colour] : {std::pair{"first", "#1f77b4"}, std::pair{"total", "#ff7f0e"}}) {
      const int bar_y = y + 18 * k++;
      const double value = NumberOr0(index[key]);
      const nlohmann::json& ci = index[std::string(key) + "_ci95"];
      s += "<rect x=\"" + std::to_string(left) + "\" y=\"" + std::to_string(bar_y) + "\" width=\"" +
           FormatFixed(IndexX(value, top, left, width) - left, 1) + "\" height=\"16\" fill=\"" + colour + "\"/>\n";
      s += "<line x1=\"" + FormatFixed(IndexX(NumberOr0(ci[0]), top, left, width), 1) + "\" y1=\"" +
           std::to_string(bar_y + 8) + "\" x2=\"" + FormatFixed(IndexX(NumberOr0(ci[1]), top, left, width), 1) +
           "\" y2=\"" + std::to_string(bar_y + 8) + "\" stroke=\"#222222\"/>\n";
      s += "<text x=\"" + std::to_string(left + width + 56) + "\" y=\"" + std::to_string(bar_y + 13) +
           "\" font-size=\"11\" text-anchor=\"end\">" + FormatFixed(value, 2) + "</text>\n";
    }
  }
  return s + "</svg>\n";
}

// a scatter plot of points sorted by x
std::string Scatter(const std::string& id, const std::string& title, const std::string& x_label, const std::string& y_label,
                    std::vector<std::pair<double, double>> points) {
  std::sort(points.begin(), points.end());
  LinePlot plot{id, title, x_label, y_label};
  plot.include_zero = false;
  PlotSeries s{"samples"};
  s.points = true, s.line = false;
  for (const auto& [x, y] : points) s.x.push_back(x), s.y.push_back(y);
  plot.series.push_back(s);
  return RenderLinePlot(plot);
}

// the mean and the 5th and 95th percentiles of the first N samples
std::string Convergence(const std::string& name, const std::vector<double>& v) {
  LinePlot plot{"plot-convergence-" + Id(name), name + ": convergence", "samples N", name};
  plot.include_zero = false;
  PlotSeries mean{"mean", {}, {}, "#1f77b4"}, p5{"P5", {}, {}, "#2ca02c", true}, p95{"P95", {}, {}, "#d62728", true};
  for (std::size_t n = 5; n <= v.size(); n += std::max<std::size_t>(1, v.size() / 60)) {
    std::vector<double> head(v.begin(), v.begin() + n);
    double sum = 0.0;
    for (double x : head) sum += x;
    std::sort(head.begin(), head.end());
    mean.x.push_back(n), mean.y.push_back(sum / n);
    p5.x.push_back(n), p5.y.push_back(Percentile(head, 0.05));
    p95.x.push_back(n), p95.y.push_back(Percentile(head, 0.95));
  }
  plot.series = {mean, p5, p95};
  return RenderLinePlot(plot);
}

std::string FailedTable(const std::vector<SampleRecord>& records) {
  std::string t = "<table id=\"table-failed\"><thead><tr><th>sample</th><th>status</th><th>why</th></tr></thead><tbody>\n";
  for (const SampleRecord& r : records) {
    if (r.in_statistics()) continue;
    const nlohmann::json j = nlohmann::json::parse(r.line);
    const std::string why = j.contains("message") ? j["message"].get<std::string>() : j.value("warnings", nlohmann::json::array()).dump();
    t += "<tr><td>" + std::to_string(r.index) + "</td><td>" + XmlEscape(r.status) + "</td><td>" + XmlEscape(why) + "</td></tr>\n";
  }
  return t + "</tbody></table>\n";
}

// the samples in the statistics that carry warnings (their results stand; the warning says what to check)
std::string WarnedTable(const std::vector<SampleRecord>& records) {
  std::string t = "<table id=\"table-warned\"><thead><tr><th>sample</th><th>warnings</th></tr></thead><tbody>\n";
  for (const SampleRecord& r : records) {
    if (!r.in_statistics() || r.warnings.empty()) continue;
    std::string codes;
    for (const std::string& code : r.warning_codes()) codes += (codes.empty() ? "" : ", ") + code;
    t += "<tr><td>" + std::to_string(r.index) + "</td><td>" + XmlEscape(codes) + "</td></tr>\n";
  }
  return t + "</tbody></table>\n";
}

std::string SpecSection(const Spec& spec, int samples) {
  std::string s = "<h2 id=\"spec\">Spec and assumptions</h2>\n<p class=\"note\">spec " + XmlEscape(spec.file) + "; base scenario " +
                  XmlEscape(spec.scenario_file) + "; spec hash " + HashText(spec.hash) + "; seed " + std::to_string(spec.seed) +
                  "; design " + kDesignKeys[static_cast<int>(spec.design)] + ", " +
                  std::to_string(samples) + " samples; engine " + kEngineVersion +
                  ". Values in the base scenario's units. Statistics use the complete samples whose warnings leave their results physical; the others are listed below.</p>\n";
  s += "<table id=\"table-inputs\"><thead><tr><th>input</th><th>path</th><th>distribution</th><th>bounds</th></tr></thead><tbody>\n";
  for (const Input& in : spec.inputs)
    s += "<tr><td>" + XmlEscape(in.name) + "</td><td>" + XmlEscape(in.path.empty() ? "(CRASH3 preset)" : in.path) + "</td><td>" +
         DistributionName(in.distribution.kind) + " (mean " + FormatFixed(Mean(in.distribution), 4) + ")</td><td>" +
         (in.low > -1e299 ? FormatFixed(in.low, 3) + " .. " + FormatFixed(in.high, 3) : std::string("none")) + "</td></tr>\n";
  return s + "</tbody></table>\n";
}

}  // namespace

std::string EnsembleReportHtml(const Spec& spec, const std::vector<SampleRecord>& records, const std::string& ensemble_json) {
  const std::map<std::string, Column> columns = Columns(records);
  const nlohmann::json statistics = nlohmann::json::parse(ensemble_json);
  const nlohmann::json outputs = statistics.value("outputs", nlohmann::json::object());
  std::string page = "<!DOCTYPE html>\n<html xmlns=\"http://www.w3.org/1999/xhtml\" lang=\"en\">\n<head>\n<meta charset=\"utf-8\"/>\n"
                     "<title>DyMESH ensemble report</title>\n<style>" + std::string(kCss) + "</style>\n</head>\n<body>\n";
  int used = 0;
  for (const SampleRecord& r : records) used += r.in_statistics();
  page += "<h1>Ensemble: " + XmlEscape(spec.file) + "</h1>\n<p>" + std::to_string(records.size()) + " samples, " +
          std::to_string(used) + " in the statistics, " + std::to_string(records.size() - used) +
          " not (listed at the end).</p>\n";
  page += "<h2 id=\"statistics\">Statistics</h2>\n" + StatisticsTable(outputs) +
          ExceedanceTable(statistics.value("exceedance", nlohmann::json::array())) + PosteriorSection(statistics);
  // per output: distributions, convergence and Sobol' bars; delta-V outputs also get a tornado and scatter plots
  for (const auto& [name, column] : columns) {
    page += "<h3>" + XmlEscape(name) + "</h3>\n<div class=\"figures\">\n" + Distributions(name, column.values) +
            Convergence(name, column.values);
    // Sobol' bars of an output that varies (a constant one has no variance to apportion)
    if (outputs.contains(name) && outputs[name].contains("sobol") && NumberOr0(outputs[name]["sd"]) > 0.0)
      page += SobolBars(name, outputs[name]["sobol"]);
    if (name.size() > 8 && name.compare(name.size() - 8, 8, ".delta_v") == 0) {
      page += Tornado(spec, name, column);
      for (std::size_t k = 0; k < spec.inputs.size(); ++k) {
        std::vector<std::pair<double, double>> points;
        for (std::size_t i = 0; i < column.values.size(); ++i) points.push_back({column.inputs[i][k], column.values[i]});
        page += Scatter("plot-scatter-" + Id(spec.inputs[k].name) + "-" + Id(name), spec.inputs[k].name + " against " + name,
                        spec.inputs[k].name, name, points);
      }
      // delta-V against PDOF of the same body
      const std::string body = name.substr(0, name.size() - 8);
      if (const auto pdof = columns.find(body + ".pdof_deg"); pdof != columns.end()) {
        std::vector<std::pair<double, double>> points;
        for (std::size_t i = 0; i < column.values.size(); ++i) points.push_back({pdof->second.values[i], column.values[i]});
        page += Scatter("plot-dv-pdof-" + Id(body), body + ": delta-V against PDOF", "PDOF [deg]", name, points);
      }
    }
    page += "</div>\n";
  }
  page += "<h2 id=\"failed\">Samples not in the statistics</h2>\n" + FailedTable(records);
  page += "<h2 id=\"warned\">Samples in the statistics with warnings</h2>\n<p class=\"note\">Their delta-V and energies "
          "stand; the warning names what is not physical (README, run warnings).</p>\n" + WarnedTable(records);
  page += SpecSection(spec, static_cast<int>(records.size()));
  return page + "</body>\n</html>\n";
}

}  // namespace dymesh::ensemble
