#include "dymesh/ensemble/spec.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "dymesh/core/run_start.h"
#include "dymesh/core/scenario.h"
#include "dymesh/ensemble/random_stream.h"
#include "dymesh/ensemble/sample_run.h"
#include "dymesh/ensemble/sobol_sequence.h"
#include "dymesh/io/json_document.h"
#include "dymesh/io/printable.h"
#include "dymesh/io/scenario_json.h"

namespace dymesh::ensemble {
namespace {

using Json = nlohmann::json;
namespace fs = std::filesystem;

// "a, b, c" for messages
template <class Names>
std::string JoinNames(const Names& names) {
  std::string list;
  for (const char* name : names) list += std::string(list.empty() ? "" : ", ") + name;
  return list;
}

// what the spec is read from, for messages
struct Reader {
  std::string file;
  // field and message as printable text: a key or a value from the spec may hold control bytes
  [[noreturn]] void Fail(const std::string& field, const std::string& message) const {
    throw InputError(file, Printable(field), Printable(message));
  }
  const Json& Require(const Json& object, const std::string& path, const char* key) const {
    if (!object.is_object() || !object.contains(key)) Fail(path.empty() ? key : path + "." + key, "missing required key");
    return object.at(key);
  }
  double Number(const Json& j, const std::string& field) const {
    if (!j.is_number() || !std::isfinite(j.get<double>())) Fail(field, "expected a finite number, got " + j.dump());
    return j.get<double>();
  }
  // an object holding only the keys listed
  void Only(const Json& object, const std::string& field, std::initializer_list<const char*> allowed) const {
    if (!object.is_object()) Fail(field, "expected an object, got " + object.dump());
    for (const auto& item : object.items()) {
      if (std::find(allowed.begin(), allowed.end(), item.key()) != allowed.end()) continue;
      Fail(field + "." + item.key(), "unknown key; allowed keys: " + JoinNames(allowed));
    }
  }
  const Json& Array(const Json& j, const std::string& field, const char* what) const {
    if (!j.is_array()) Fail(field, std::string("expected an array of ") + what + ", got " + j.dump());
    return j;
  }
};

std::string ReadText(const std::string& path, const std::string& spec_file, const std::string& field) {
  if (const std::string problem = NotARegularFile(path); !problem.empty())
    throw InputError(spec_file, field, problem + ": " + path);
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// the contents of the files a scenario reads besides itself: each body's vehicle file and mesh file
std::string FilesReadBy(const Scenario& scenario, const std::string& spec_file) {
  std::string contents;
  for (std::size_t i = 0; i < scenario.bodies.size(); ++i)
    for (const std::string& file : {scenario.bodies[i].vehicle_file, scenario.bodies[i].mesh.file})
      if (!file.empty()) contents += "\n" + ReadText(file, spec_file, "scenario (bodies[" + std::to_string(i) + "])");
  return contents;
}

// bodies[0].initial.speed -> /bodies/0/initial/speed: keys joined by '.', each followed by any
// number of [index] (digits); nothing else
std::string PointerOf(const Reader& r, const std::string& path, const std::string& field) {
  const std::string expected = "expected a JSON path into the scenario such as bodies[0].initial.speed, got \"" + path + "\"";
  std::string pointer;
  std::size_t i = 0;
  while (true) {
    // a key: letters, digits and underscores
    const std::size_t start = i;
    while (i < path.size() && (std::isalnum(static_cast<unsigned char>(path[i])) || path[i] == '_')) ++i;
    if (i == start) r.Fail(field, expected);
    pointer.push_back('/');
    pointer.append(path, start, i - start);
    // its indices
    while (i < path.size() && path[i] == '[') {
      const std::size_t digits = ++i;
      while (i < path.size() && std::isdigit(static_cast<unsigned char>(path[i]))) ++i;
      if (i == digits || i - digits > 6 || i >= path.size() || path[i] != ']') r.Fail(field, expected);
      pointer.push_back('/');
      pointer.append(std::to_string(std::stoi(path.substr(digits, i - digits))));
      ++i;
    }
    if (i == path.size()) return pointer;
    if (path[i] != '.') r.Fail(field, expected);
    ++i;
  }
}

// one distribution: {"KIND": {parameters}}
Distribution ParseDistribution(const Reader& r, const Json& j, const std::string& field) {
  if (!j.is_object() || j.size() != 1) r.Fail(field, "expected one of {\"fixed\": ...}, {\"uniform\": ...}, {\"normal\": ...}, "
                                                     "{\"truncated_normal\": ...}, {\"triangular\": ...}, {\"pert\": ...}, {\"beta\": ...}, "
                                                     "{\"lognormal\": ...}, {\"discrete\": ...}");
  const std::string kind = j.begin().key();
  const Json& p = j.begin().value();
  const std::string at = field + "." + kind;
  if (kind != "fixed") {
    if (kind == "uniform") r.Only(p, at, {"low", "high"});
    else if (kind == "normal") r.Only(p, at, {"mean", "sd", "value", "band95"});
    else if (kind == "truncated_normal") r.Only(p, at, {"mean", "sd", "value", "band95", "low", "high"});
    else if (kind == "triangular" || kind == "pert") r.Only(p, at, {"low", "mode", "high"});
    else if (kind == "lognormal") r.Only(p, at, {"median", "sigma"});
    else if (kind == "beta") r.Only(p, at, {"alpha", "beta", "low", "high"});
    else if (kind == "discrete") r.Only(p, at, {"values", "weights"});
  }
  auto num = [&](const char* key) { return r.Number(r.Require(p, at, key), at + "." + key); };
  Distribution d;
  if (kind == "fixed") {
    d.kind = DistributionKind::kFixed, d.a = r.Number(p, at);
  } else if (kind == "uniform") {
    d.kind = DistributionKind::kUniform, d.a = num("low"), d.b = num("high");
    if (!(d.b > d.a)) r.Fail(at + ".high", "expected high > low");
  } else if (kind == "normal" || kind == "truncated_normal") {
    d.kind = kind == "normal" ? DistributionKind::kNormal : DistributionKind::kTruncatedNormal;
    // mean and sd, or a value with its 95 % band (sd = band / 1.96): one form, never both
    if ((p.contains("value") || p.contains("band95")) && (p.contains("mean") || p.contains("sd")))
      r.Fail(at, "give mean and sd, or value and band95, not both (one would be ignored)");
    if (p.contains("band95")) {
      d.a = num("value"), d.b = num("band95") / 1.959963984540054;
    } else {
      d.a = num("mean"), d.b = num("sd");
    }
    if (!(d.b > 0.0)) r.Fail(at, "expected a standard deviation (or band95) > 0");
    if (d.kind == DistributionKind::kTruncatedNormal) {
      d.c = num("low"), d.d = num("high");
      if (!(d.d > d.c)) r.Fail(at + ".high", "expected high > low");
    }
  } else if (kind == "triangular") {
    d.kind = DistributionKind::kTriangular, d.a = num("low"), d.b = num("mode"), d.c = num("high");
    if (!(d.a <= d.b && d.b <= d.c && d.c > d.a)) r.Fail(at, "expected low <= mode <= high, low < high");
  } else if (kind == "lognormal") {
    d.kind = DistributionKind::kLognormal, d.a = num("median"), d.b = num("sigma");
    if (!(d.a > 0.0 && d.b > 0.0)) r.Fail(at, "expected median > 0 and sigma > 0");
  } else if (kind == "beta") {
    d.kind = DistributionKind::kBeta, d.a = num("alpha"), d.b = num("beta");
    d.c = p.contains("low") ? num("low") : 0.0, d.d = p.contains("high") ? num("high") : 1.0;
    if (!(d.a > 0.0 && d.b > 0.0)) r.Fail(at, "expected alpha > 0 and beta > 0");
    if (!(d.d > d.c)) r.Fail(at + ".high", "expected high > low");
  } else if (kind == "pert") {
    d.kind = DistributionKind::kPert, d.a = num("low"), d.b = num("mode"), d.c = num("high");
    if (!(d.a <= d.b && d.b <= d.c && d.c > d.a)) r.Fail(at, "expected low <= mode <= high, low < high");
  } else if (kind == "discrete") {
    d.kind = DistributionKind::kDiscrete;
    const Json& values = r.Require(p, at, "values");
    if (!values.is_array() || values.empty()) r.Fail(at + ".values", "expected a non-empty array of numbers");
    if (p.contains("weights") && (!p["weights"].is_array() || p["weights"].size() != values.size()))
      r.Fail(at + ".weights", "expected an array of " + std::to_string(values.size()) + " weights, one per value");
    double total = 0.0;
    for (std::size_t i = 0; i < values.size(); ++i) {
      d.values.push_back(r.Number(values[i], at + ".values[" + std::to_string(i) + "]"));
      const double w = p.contains("weights") ? r.Number(p["weights"][i], at + ".weights[" + std::to_string(i) + "]") : 1.0;
      if (!(w > 0.0)) r.Fail(at + ".weights[" + std::to_string(i) + "]", "expected a weight > 0");
      d.cumulative.push_back(total += w);
    }
  } else {
    r.Fail(field, "unknown distribution \"" + kind + "\"");
  }
  // every draw a finite number: parameters at the edge of double range, or a truncation window
  // beyond the normal's reach (its probability rounds to 0), leave none
  bool finite = std::isfinite(Mean(d));
  for (double u : {1e-12, 1e-6, 0.5, 1.0 - 1e-6, 1.0 - 1e-12}) finite = finite && std::isfinite(Quantile(d, u));
  if (!finite) r.Fail(at, "these parameters give draws that are not finite numbers");
  return d;
}

// the distribution's support must meet the bounds, and its likely range lie inside them
void CheckBounds(const Reader& r, const Input& in, const std::string& field) {
  const double lo = Quantile(in.distribution, 1e-6), hi = Quantile(in.distribution, 1 - 1e-6);
  if (hi < in.low || lo > in.high)
    r.Fail(field, "the bounds [" + std::to_string(in.low) + ", " + std::to_string(in.high) +
                      "] exclude the distribution's support: no sample could be drawn");
}

Input ParseInput(const Reader& r, const Json& j, const Json& scenario, const std::string& field) {
  Input in;
  r.Only(j, field, {"name", "path", "distribution", "bounds", "levels"});
  const Json& name = r.Require(j, field, "name");
  if (!name.is_string() || name.get<std::string>().empty()) r.Fail(field + ".name", "expected a non-empty name");
  in.name = name.get<std::string>();
  const Json& path = r.Require(j, field, "path");
  if (!path.is_string()) r.Fail(field + ".path", "expected a JSON path string");
  in.path = path.get<std::string>();
  in.pointer = PointerOf(r, in.path, field + ".path");
  // the path must reach into the scenario: a number there, or a key to create in an object there
  const Json::json_pointer pointer(in.pointer);
  if (!scenario.contains(pointer.parent_pointer()) ||
      (!scenario.at(pointer.parent_pointer()).is_object() && !scenario.contains(pointer)))
    r.Fail(field + ".path", "\"" + in.path + "\" does not lead into the scenario (its parent is missing, or an "
                            "array index is beyond the array's end)");
  if (scenario.contains(pointer) && !scenario.at(pointer).is_number())
    r.Fail(field + ".path", "\"" + in.path + "\" leads to " + scenario.at(pointer).dump() + " in the scenario, not a number");
  in.distribution = ParseDistribution(r, r.Require(j, field, "distribution"), field + ".distribution");
  if (j.contains("levels")) {
    const double levels = r.Number(j["levels"], field + ".levels");
    if (levels < 1 || levels > 1000 || std::floor(levels) != levels) r.Fail(field + ".levels", "expected an integer in 1..1000");
    in.levels = static_cast<int>(levels);
  }
  if (j.contains("bounds")) {
    const Json& b = j["bounds"];
    if (!b.is_array() || b.size() != 2) r.Fail(field + ".bounds", "expected [low, high]");
    in.low = r.Number(b[0], field + ".bounds[0]"), in.high = r.Number(b[1], field + ".bounds[1]");
    if (!(in.high >= in.low)) r.Fail(field + ".bounds", "expected low <= high");
    CheckBounds(r, in, field + ".bounds");
  }
  return in;
}

// "crash3": [{name, body, surface, width, weight (US, lb) | mass (SI, kg), b0, b1}]: two inputs and
// the preset that turns them into the surface's A and B
void ParseCrash3(const Reader& r, const Json& list, const Json& scenario, const Scenario& base, Spec* spec) {
  if (!list.is_array()) r.Fail("crash3", "expected an array of presets");
  const bool us = scenario.value("units", "US") == "US";
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string at = "crash3[" + std::to_string(i) + "]";
    const Json& j = list[i];
    r.Only(j, at, {"name", "body", "surface", "width", us ? "weight" : "mass", "b0", "b1"});
    const Json& name = r.Require(j, at, "name");
    if (!name.is_string() || name.get<std::string>().empty()) r.Fail(at + ".name", "expected a non-empty name");
    const double body = r.Number(r.Require(j, at, "body"), at + ".body");
    const std::size_t bodies = scenario.contains("bodies") ? scenario["bodies"].size() : 0;
    if (body < 0 || body >= bodies || std::floor(body) != body)
      r.Fail(at + ".body", "expected a body index of the scenario, 0.." + std::to_string(static_cast<int>(bodies) - 1));
    const Json& surface = r.Require(j, at, "surface");
    const std::string s = surface.is_string() ? surface.get<std::string>() : "";
    if (s != "front" && s != "right" && s != "back" && s != "left" && s != "top" && s != "bottom")
      r.Fail(at + ".surface", "expected front, right, back, left, top or bottom");
    if (base.bodies[static_cast<std::size_t>(body)].rigid)
      r.Fail(at + ".body", "body " + std::to_string(static_cast<int>(body)) + " (\"" +
                               base.bodies[static_cast<std::size_t>(body)].name + "\") is rigid: it takes no crush, so "
                               "its stiffness is never used");
    Crash3Preset preset;
    preset.us = us;
    preset.pointer = "/bodies/" + std::to_string(static_cast<int>(body)) + "/stiffness/" + s;
    // one source per surface's coefficients: another preset or an input would be overwritten
    const std::string named = "bodies[" + std::to_string(static_cast<int>(body)) + "] " + s;
    for (std::size_t k = 0; k < spec->crash3.size(); ++k)
      if (spec->crash3[k].pointer == preset.pointer)
        r.Fail(at + ".surface", named + " is already set by crash3[" + std::to_string(k) + "]");
    for (std::size_t k = 0; k < spec->inputs.size(); ++k)
      if (spec->inputs[k].pointer.rfind(preset.pointer + "/", 0) == 0)
        r.Fail(at + ".surface", named + " is also set by inputs[" + std::to_string(k) + "] (\"" + spec->inputs[k].path +
                                    "\"): give its stiffness one source");
    preset.width = r.Number(r.Require(j, at, "width"), at + ".width");
    const char* mass_key = us ? "weight" : "mass";
    preset.mass = r.Number(r.Require(j, at, mass_key), at + "." + mass_key) * (us ? 0.45359237 : 1.0);
    if (!(preset.width > 0.0) || !(preset.mass > 0.0)) r.Fail(at, std::string("expected width > 0 and ") + mass_key + " > 0");
    // b0 and b1 are inputs of their own (their own streams), positive everywhere they can fall
    for (const char* coefficient : {"b0", "b1"}) {
      Input in;
      in.name = name.get<std::string>() + "." + coefficient;
      in.distribution = ParseDistribution(r, r.Require(j, at, coefficient), at + "." + coefficient);
      if (!(Quantile(in.distribution, 1e-9) > 0.0)) r.Fail(at + "." + coefficient, "expected a distribution of positive values");
      (std::string(coefficient) == "b0" ? preset.b0_input : preset.b1_input) = static_cast<int>(spec->inputs.size());
      spec->inputs.push_back(in);
    }
    spec->crash3.push_back(preset);
  }
}

// "correlation": {"inputs": [names], "rank_matrix": [[...]]}: Spearman correlations, positive definite
void ParseCorrelation(const Reader& r, const Json& j, Spec* spec) {
  r.Only(j, "correlation", {"inputs", "rank_matrix"});
  const Json& names = r.Require(j, "correlation", "inputs");
  const Json& matrix = r.Require(j, "correlation", "rank_matrix");
  if (!names.is_array() || names.size() < 2) r.Fail("correlation.inputs", "expected at least two input names");
  const int n = static_cast<int>(names.size());
  for (int a = 0; a < n; ++a) {
    int index = -1;
    for (std::size_t k = 0; k < spec->inputs.size(); ++k)
      if (names[a].is_string() && spec->inputs[k].name == names[a].get<std::string>()) index = static_cast<int>(k);
    const std::string at = "correlation.inputs[" + std::to_string(a) + "]";
    if (index < 0) r.Fail(at, "expected the name of an input, got " + names[a].dump());
    for (int earlier : spec->correlation.inputs)
      if (earlier == index) r.Fail(at, "input \"" + names[a].get<std::string>() + "\" is named twice");
    spec->correlation.inputs.push_back(index);
  }
  // the shape first, then the values (a symmetric pair reads a row not yet reached)
  if (!matrix.is_array() || static_cast<int>(matrix.size()) != n)
    r.Fail("correlation.rank_matrix", "expected a " + std::to_string(n) + " x " + std::to_string(n) + " matrix");
  for (int a = 0; a < n; ++a)
    if (!matrix[a].is_array() || static_cast<int>(matrix[a].size()) != n)
      r.Fail("correlation.rank_matrix[" + std::to_string(a) + "]", "expected a row of " + std::to_string(n) + " numbers");
  Eigen::MatrixXd pearson(n, n);
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      const std::string at = "correlation.rank_matrix[" + std::to_string(a) + "][" + std::to_string(b) + "]";
      const double rho = r.Number(matrix[a][b], at);
      if (a == b && rho != 1.0) r.Fail(at, "expected 1 on the diagonal");
      if (std::abs(rho) > 1.0) r.Fail(at, "expected a correlation in [-1, 1]");
      if (rho != r.Number(matrix[b][a], at)) r.Fail(at, "expected a symmetric matrix");
      // the normal scores' correlation that gives this rank correlation
      pearson(a, b) = 2.0 * std::sin(3.14159265358979323846 * rho / 6.0);
    }
  Eigen::LLT<Eigen::MatrixXd> llt(pearson);
  if (llt.info() != Eigen::Success || llt.matrixL().toDenseMatrix().diagonal().minCoeff() < 1e-12)
    r.Fail("correlation.rank_matrix", "is not positive definite: no joint distribution has these correlations");
  spec->correlation.cholesky = llt.matrixL();
}

// keys a design does not read: `samples` where the design counts its own runs (grid: the levels,
// one-at-a-time: the inputs, table: the rows), `table` beside another design, `levels` beside
// another design than grid
void RefuseKeysTheDesignIgnores(const Reader& r, const Json& j, Design design) {
  const char* name = kDesignKeys[static_cast<int>(design)];
  const char* count = design == Design::kGrid         ? "the product of the inputs' levels"
                      : design == Design::kOneAtATime ? "1 + 2 x the inputs"
                      : design == Design::kTable      ? "the rows of table"
                                                      : nullptr;
  if (count != nullptr && j.contains("samples"))
    r.Fail("samples", std::string("the design \"") + name + "\" sets its own run count (" + count + "): remove samples");
  if (design != Design::kTable && j.contains("table"))
    r.Fail("table", std::string("is read only by the design \"table\"; this spec's design is \"") + name + "\"");
  for (std::size_t i = 0; design != Design::kGrid && i < j["inputs"].size(); ++i)
    if (j["inputs"][i].contains("levels"))
      r.Fail("inputs[" + std::to_string(i) + "].levels",
             std::string("is read only by the design \"grid\"; this spec's design is \"") + name + "\"");
}

// grid, one-at-a-time and table designs: their sample count, and the table's rows
void SizeDeterministicDesign(const Reader& r, const Json& j, Spec* spec) {
  const std::size_t k = spec->inputs.size();
  if (spec->design == Design::kGrid) {
    double runs = 1;
    for (const Input& in : spec->inputs) runs *= in.levels;
    if (runs > 1e7) r.Fail("inputs", "the grid would have more than 1e7 runs");
    spec->samples = static_cast<int>(runs);
  } else if (spec->design == Design::kOneAtATime) {
    spec->samples = static_cast<int>(1 + 2 * k);
  } else if (spec->design == Design::kTable) {
    const Json& table = r.Require(j, "", "table");
    if (!table.is_array() || table.empty()) r.Fail("table", "expected an array of rows, one value per input");
    for (std::size_t row = 0; row < table.size(); ++row) {
      const std::string at = "table[" + std::to_string(row) + "]";
      if (!table[row].is_array() || table[row].size() != k)
        r.Fail(at, "expected " + std::to_string(k) + " values (one per input, in input order)");
      std::vector<double> values;
      for (std::size_t c = 0; c < k; ++c) values.push_back(r.Number(table[row][c], at + "[" + std::to_string(c) + "]"));
      spec->table.push_back(values);
    }
    spec->samples = static_cast<int>(spec->table.size());
  }
  const bool deterministic =
      spec->design == Design::kGrid || spec->design == Design::kOneAtATime || spec->design == Design::kTable;
  if (deterministic && !spec->correlation.inputs.empty())
    r.Fail("correlation", "a grid, one-at-a-time or table design has no random draws to correlate");
}

// "BODY.QUANTITY": a body of the scenario and a per-body output (or, for evidence, an observable)
bool IsQuantityOf(const Scenario& scenario, const Json& name, bool observable) {
  if (!name.is_string()) return false;
  const std::string text = name.get<std::string>();
  const std::size_t dot = text.rfind('.');
  if (dot == std::string::npos) return false;
  bool body = false;
  for (const BodySpec& b : scenario.bodies) body = body || b.name == text.substr(0, dot);
  const std::string q = text.substr(dot + 1);
  auto among = [&](const auto& names) { return std::find(names.begin(), names.end(), q) != names.end(); };
  return body && (among(kOutputQuantities) || (observable && among(kMeasuredQuantities)));
}

// the sample's scenario as a run starts it: parsed, its bodies built (meshes from `meshes`), and
// what a run refuses before its first step (placement, a fixed body given motion, the stable step)
void StartSample(const Spec& spec, const std::vector<double>& values, MeshCache* meshes) {
  Scenario scenario = SampleScenario(spec, values);
  CheckRunStart(&scenario, SampleModels(scenario, meshes));
}

// input i at `value`, for messages: inputs[1] ("speed" = 45), or a CRASH3 preset's input
std::string InputAt(const Spec& spec, std::size_t i, double value) {
  const std::string named = "\"" + spec.inputs[i].name + "\" = " + Json(value).dump();
  return spec.inputs[i].pointer.empty() ? "crash3 input " + named : "inputs[" + std::to_string(i) + "] (" + named + ")";
}

// every input at its median, then each alone at its extremes (within its bounds): a run must start
// from them, so that a path or a distribution it cannot take is refused before any sample runs
void TrySampleScenarios(const Reader& r, const Spec& spec) {
  const std::size_t k = spec.inputs.size();
  auto clamp = [&](std::size_t i, double u) {
    return std::clamp(Quantile(spec.inputs[i].distribution, u), spec.inputs[i].low, spec.inputs[i].high);
  };
  std::vector<double> median(k);
  for (std::size_t i = 0; i < k; ++i) median[i] = clamp(i, 0.5);
  MeshCache meshes;  // each mesh source built once for all the trials
  // the trial's inputs named (input i alone, or all of them at their medians when i == k)
  auto attempt = [&](const std::vector<double>& values, std::size_t i) {
    try {
      StartSample(spec, values, &meshes);
    } catch (const InputError& e) {
      std::string which = i < k ? InputAt(spec, i, values[i]) : "";
      for (std::size_t m = 0; i == k && m < k; ++m) which += (m ? ", " : "inputs at their medians: ") + InputAt(spec, m, values[m]);
      r.Fail(which.empty() ? "inputs" : which, "the scenario refuses this sample: " + std::string(e.what()));
    }
  };
  attempt(median, k);
  for (std::size_t i = 0; i < k; ++i)
    for (double u : {1e-6, 1.0 - 1e-6}) {
      std::vector<double> values = median;
      values[i] = clamp(i, u);
      attempt(values, i);
    }
}

}  // namespace

std::string HashText(std::uint64_t hash) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

Spec LoadSpec(const std::string& path) {
  const Reader r{path};
  Spec spec;
  spec.file = path;
  // strict: a duplicate key, a number out of range or malformed JSON is refused at its field
  const Json j = ParseJsonDocument(ReadText(path, path, "(file)"), path);
  if (!j.is_object()) r.Fail("(root)", "expected an object");
  for (const auto& item : j.items())
    if (item.key() != "scenario" && item.key() != "inputs" && item.key() != "design" && item.key() != "samples" &&
        item.key() != "seed" && item.key() != "thresholds" && item.key() != "crash3" && item.key() != "correlation" &&
        item.key() != "table" && item.key() != "evidence" && item.key() != "stop_tolerance")
      r.Fail(item.key(), "unknown key; allowed keys: scenario, inputs, crash3, correlation, design, samples, seed, "
                         "thresholds, table, evidence, stop_tolerance");
  // the base scenario, relative to the spec
  const Json& scenario = r.Require(j, "", "scenario");
  if (!scenario.is_string()) r.Fail("scenario", "expected a scenario file name");
  fs::path base(scenario.get<std::string>());
  if (base.is_relative()) base = fs::absolute(fs::path(path)).parent_path() / base;
  spec.scenario_file = base.lexically_normal().string();
  spec.scenario_text = ReadText(spec.scenario_file, path, "scenario");
  const Scenario base_scenario = LoadScenario(spec.scenario_file);  // the base must be valid on its own
  spec.input_files = InputFiles(base_scenario);
  spec.input_files.push_back(path);
  const Json scenario_json = Json::parse(spec.scenario_text);
  // inputs, design, size, seed, thresholds
  const Json& inputs = r.Require(j, "", "inputs");
  if (!inputs.is_array()) r.Fail("inputs", "expected an array");
  for (std::size_t i = 0; i < inputs.size(); ++i)
    spec.inputs.push_back(ParseInput(r, inputs[i], scenario_json, "inputs[" + std::to_string(i) + "]"));
  if (j.contains("crash3")) ParseCrash3(r, j["crash3"], scenario_json, base_scenario, &spec);
  for (std::size_t a = 0; a < spec.inputs.size(); ++a)
    for (std::size_t b = 0; b < a; ++b) {
      if (spec.inputs[a].name == spec.inputs[b].name) r.Fail("inputs", "duplicate input name \"" + spec.inputs[a].name + "\"");
      if (!spec.inputs[a].pointer.empty() && spec.inputs[a].pointer == spec.inputs[b].pointer)
        r.Fail("inputs[" + std::to_string(a) + "].path", "\"" + spec.inputs[a].path + "\" is already set by inputs[" +
                                                             std::to_string(b) + "]");
    }
  if (j.contains("correlation")) ParseCorrelation(r, j["correlation"], &spec);
  if (j.contains("design")) {
    const std::string d = j["design"].is_string() ? j["design"].get<std::string>() : "";
    const auto key = std::find(kDesignKeys.begin(), kDesignKeys.end(), d);
    if (key == kDesignKeys.end()) {
      std::string keys;
      for (const char* k : kDesignKeys) keys += (keys.empty() ? "\"" : ", \"") + std::string(k) + "\"";
      r.Fail("design", "expected one of " + keys + ", got " + j["design"].dump());
    }
    spec.design = static_cast<Design>(key - kDesignKeys.begin());
  }
  RefuseKeysTheDesignIgnores(r, j, spec.design);
  if (j.contains("samples")) {
    const double n = r.Number(j["samples"], "samples");
    if (n < 1 || n > 1e7 || std::floor(n) != n) r.Fail("samples", "expected an integer in 1..1e7");
    spec.samples = static_cast<int>(n);
  }
  if (j.contains("seed")) {
    const double s = r.Number(j["seed"], "seed");
    if (s < 0 || s > 9.007e15 || std::floor(s) != s) r.Fail("seed", "expected a non-negative integer");
    spec.seed = static_cast<std::uint64_t>(s);
  }
  if (j.contains("thresholds"))
    for (std::size_t i = 0; i < r.Array(j["thresholds"], "thresholds", "thresholds").size(); ++i) {
      const std::string at = "thresholds[" + std::to_string(i) + "]";
      const Json& t = j["thresholds"][i];
      r.Only(t, at, {"output", "above"});
      const Json& output = r.Require(t, at, "output");
      if (!IsQuantityOf(base_scenario, output, false))
        r.Fail(at + ".output", "expected BODY.QUANTITY with a body of the scenario and one of " +
                                   JoinNames(kOutputQuantities) + ", got " + output.dump());
      spec.thresholds.push_back({output.get<std::string>(), r.Number(r.Require(t, at, "above"), at + ".above")});
    }
  if (j.contains("evidence")) {
    if (!j["evidence"].is_array()) r.Fail("evidence", "expected an array of measurements");
    for (std::size_t i = 0; i < j["evidence"].size(); ++i) {
      const std::string at = "evidence[" + std::to_string(i) + "]";
      const Json& e = j["evidence"][i];
      r.Only(e, at, {"observable", "value", "sd"});
      const Json& observable = r.Require(e, at, "observable");
      if (!IsQuantityOf(base_scenario, observable, true))
        r.Fail(at + ".observable", "expected BODY.QUANTITY with a body of the scenario and an output, c1..c6, rest_x, "
                                   "rest_y or rest_heading, e.g. \"p406.delta_v\" or \"p406.c3\", got " + observable.dump());
      const double sd = r.Number(r.Require(e, at, "sd"), at + ".sd");
      if (!(sd > 0.0)) r.Fail(at + ".sd", "expected a standard deviation > 0");
      spec.evidence.push_back({observable.get<std::string>(), r.Number(r.Require(e, at, "value"), at + ".value"), sd});
    }
  }
  if (j.contains("stop_tolerance")) {
    const Json& t = j["stop_tolerance"];
    r.Only(t, "stop_tolerance", {"relative", "min_samples"});
    spec.stop_relative = r.Number(r.Require(t, "stop_tolerance", "relative"), "stop_tolerance.relative");
    const double m = t.contains("min_samples") ? r.Number(t["min_samples"], "stop_tolerance.min_samples")
                                               : kDefaultStopMinSamples;
    if (!(spec.stop_relative > 0.0 && spec.stop_relative < 1.0)) r.Fail("stop_tolerance.relative", "expected a value in (0, 1)");
    if (m < 2 || std::floor(m) != m) r.Fail("stop_tolerance.min_samples", "expected an integer >= 2");
    spec.stop_min_samples = static_cast<int>(m);
    if (spec.design != Design::kMonteCarlo && spec.design != Design::kLatinHypercube && spec.design != Design::kSobol)
      r.Fail("stop_tolerance", "needs a random design (monte_carlo, latin_hypercube or sobol)");
  }
  if (spec.design == Design::kSobol && spec.inputs.size() > static_cast<std::size_t>(kSobolDimensions))
    r.Fail("design", "the Sobol' sequence has " + std::to_string(kSobolDimensions) + " dimensions; this spec has " +
                         std::to_string(spec.inputs.size()) + " inputs");
  // deterministic designs set their own sample count
  SizeDeterministicDesign(r, j, &spec);
  // Saltelli: `samples` counts the rows of A and B; each row runs inputs + 2 times
  if (spec.design == Design::kSaltelli) {
    if (!spec.correlation.inputs.empty()) r.Fail("correlation", "Sobol' indices (design \"saltelli\") need independent inputs");
    if (spec.inputs.empty()) r.Fail("inputs", "Sobol' indices need at least one input");
    spec.base_samples = spec.samples;
    spec.samples = spec.base_samples * (static_cast<int>(spec.inputs.size()) + 2);
  }
  TrySampleScenarios(r, spec);
  // the hash covers what the samples depend on: the spec itself, the base scenario's text and the
  // contents of the vehicle and mesh files it reads (a resume after one was edited is refused)
  spec.hash = TextHash(j.dump() + "\n" + spec.scenario_text + FilesReadBy(base_scenario, path));
  return spec;
}

}  // namespace dymesh::ensemble
