#include "dymesh/ensemble/ensemble_report.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <map>

#include "dymesh/ensemble/statistics.h"
#include "dymesh/report/svg_plot.h"

namespace dymesh::ensemble {
namespace {

constexpr const char* kCss = R"(
body { font-family: sans-serif; margin: 16px; color: #222222; }
table { border-collapse: collapse; margin: 8px 0 16px; font-size: 13px; }
th, td { border-bottom: 1px solid #dddddd; padding: 3px 8px; text-align: right; }
th:first-child, td:first-child { text-align: left; }
.figures { display: flex; flex-wrap: wrap; gap: 18px; }
.note { font-size: 12px; color: #555555; max-width: 900px; }
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

std::string StatisticsTable(const std::map<std::string, OutputStatistics>& stats) {
  std::string t = "<table id=\"table-statistics\"><thead><tr><th>output</th><th>n</th><th>mean</th><th>SD</th><th>P5</th>"
                  "<th>P50</th><th>P95</th><th>min</th><th>max</th></tr></thead><tbody>\n";
  for (const auto& [name, s] : stats)
    t += "<tr><td>" + XmlEscape(name) + "</td><td>" + std::to_string(s.n) + "</td><td>" + FormatFixed(s.mean, 3) + "</td><td>" +
         FormatFixed(s.sd, 3) + "</td><td>" + FormatFixed(s.p5, 3) + "</td><td>" + FormatFixed(s.p50, 3) + "</td><td>" +
         FormatFixed(s.p95, 3) + "</td><td>" + FormatFixed(s.min, 3) + "</td><td>" + FormatFixed(s.max, 3) + "</td></tr>\n";
  return t + "</tbody></table>\n";
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

std::string EnsembleReportHtml(const Spec& spec, const std::vector<SampleRecord>& records) {
  const std::map<std::string, Column> columns = Columns(records);
  const auto stats = ComputeStatistics(records);
  std::string page = "<!DOCTYPE html>\n<html xmlns=\"http://www.w3.org/1999/xhtml\" lang=\"en\">\n<head>\n<meta charset=\"utf-8\"/>\n"
                     "<title>DyMESH ensemble report</title>\n<style>" + std::string(kCss) + "</style>\n</head>\n<body>\n";
  int used = 0;
  for (const SampleRecord& r : records) used += r.in_statistics();
  page += "<h1>Ensemble: " + XmlEscape(spec.file) + "</h1>\n<p>" + std::to_string(records.size()) + " samples, " +
          std::to_string(used) + " in the statistics, " + std::to_string(records.size() - used) +
          " not (listed at the end).</p>\n";
  page += "<h2 id=\"statistics\">Statistics</h2>\n" + StatisticsTable(stats);
  // per output: distributions and convergence; delta-V outputs also get a tornado and scatter plots
  for (const auto& [name, column] : columns) {
    page += "<h3>" + XmlEscape(name) + "</h3>\n<div class=\"figures\">\n" + Distributions(name, column.values) +
            Convergence(name, column.values);
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
  page += SpecSection(spec, static_cast<int>(records.size()));
  return page + "</body>\n</html>\n";
}

}  // namespace dymesh::ensemble
