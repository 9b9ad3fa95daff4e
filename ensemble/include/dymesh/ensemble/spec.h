#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "dymesh/ensemble/distribution.h"

/// An ensemble spec: a base scenario, named uncertain inputs (each a JSON path into the scenario,
/// a distribution and hard bounds), a design, a seed and exceedance thresholds. Values are in the
/// base scenario's units.
namespace dymesh::ensemble {

/// kSaltelli: Sobol' indices by Saltelli's design: `base_samples` rows of two independent matrices
/// A and B and, per input i, A with column i from B; run k in group j = k / (n + 2): 0 is A, 1 is B,
/// 2 + i is AB_i.
/// kGrid: every combination of each input's `levels` equal-probability quantiles (mixed radix, the
/// first input fastest). kOneAtATime: run 0 at every input's median, then per input i run 1 + 2i at
/// its 5th and 2 + 2i at its 95th percentile, the others at their medians. kTable: the spec's rows.
/// kSobol: the Owen-scrambled Sobol' sequence (one dimension per input, in input order).
enum class Design { kMonteCarlo, kLatinHypercube, kSaltelli, kGrid, kOneAtATime, kTable, kSobol };
/// The designs' keys in a spec's `design`, in Design's order.
inline constexpr std::array<const char*, 7> kDesignKeys = {"monte_carlo", "latin_hypercube", "saltelli", "grid",
                                                           "one_at_a_time", "table", "sobol"};

/// The first checkpoint of a stop tolerance when the spec gives no `min_samples`.
inline constexpr int kDefaultStopMinSamples = 50;

struct Input {
  std::string name;
  std::string path{};    ///< JSON path into the scenario, e.g. bodies[0].initial.speed
  std::string pointer{}; ///< the same as a JSON pointer, /bodies/0/initial/speed; empty for a preset's input
  Distribution distribution{};
  double low = -1e300, high = 1e300;  ///< hard physical bounds: a sample outside is refused
  int levels = 3;                     ///< grid design: quantile levels of this input
};

/// P(output > above): the output is "BODY.QUANTITY" (e.g. "p406.delta_v").
struct Threshold {
  std::string output;
  double above = 0.0;
};

/// A measurement the samples are weighed against: the observable (an output "BODY.QUANTITY", or
/// "BODY.c1".."BODY.c6", "BODY.rest_x", "BODY.rest_y", "BODY.rest_heading"), its measured value and
/// its standard deviation (scenario units); each complete sample gets the Gaussian likelihood.
struct Evidence {
  std::string observable;
  double value = 0.0, sd = 1.0;
};

/// CRASH3 stiffness of one body surface from sampled b0 (no-damage speed) and b1 (slope): never A
/// and B independently. A = m b0 b1 / L, B = m b1^2 / L (m the mass, L the damage width), written
/// as the surface's 2-D coefficients.
struct Crash3Preset {
  int b0_input = -1, b1_input = -1;  ///< the two inputs (named NAME.b0, NAME.b1) that carry b0 and b1
  std::string pointer;               ///< JSON pointer of the surface object, /bodies/0/stiffness/front
  double mass = 0.0;                 ///< [kg]
  double width = 0.0;                ///< L, scenario length unit
  bool us = true;                    ///< b0 in mph, b1 in mph/in, width in in; else m/s, 1/s, m
};

/// Gaussian copula over some inputs: their rank correlations as the Cholesky factor of the
/// normal-score correlation (r = 2 sin(pi rho_s / 6)).
struct Correlation {
  std::vector<int> inputs;
  Eigen::MatrixXd cholesky;
};

struct Spec {
  std::string file;            ///< the spec's path (messages)
  std::string scenario_file;   ///< the base scenario, absolute
  std::string scenario_text;   ///< its JSON text as read
  std::vector<std::string> input_files;  ///< the spec, the base scenario and the vehicle and mesh files it reads
  std::vector<Input> inputs;
  Design design = Design::kLatinHypercube;
  int samples = 100;            ///< runs (Saltelli: base_samples * (inputs + 2))
  int base_samples = 0;         ///< Saltelli: rows of A and B
  std::vector<std::vector<double>> table;  ///< table design: one row of input values per sample
  std::uint64_t seed = 1;
  std::vector<Threshold> thresholds;
  std::vector<Evidence> evidence;
  double stop_relative = 0.0;   ///< stop once mean, P5 and P95 of every output move less than this (relative)
  int stop_min_samples = 0;     ///< ... between checkpoints at min, 2 min, 4 min, ... samples
  std::vector<Crash3Preset> crash3;
  Correlation correlation;
  std::uint64_t hash = 0;      ///< of the spec and the base scenario text: records carry it
};

/// Reads and validates a spec; refusals (InputError) name the spec file, the field and what was
/// expected: a bad path, a distribution parameter out of its domain, bounds that exclude the
/// distribution's support, an unknown design.
Spec LoadSpec(const std::string& path);

/// Spec hash as 16 hex digits.
std::string HashText(std::uint64_t hash);

}  // namespace dymesh::ensemble
