#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "dymesh/ensemble/distribution.h"

/// An ensemble spec: a base scenario, named uncertain inputs (each a JSON path into the scenario,
/// a distribution and hard bounds), a design, a seed and exceedance thresholds. Values are in the
/// base scenario's units.
namespace dymesh::ensemble {

enum class Design { kMonteCarlo, kLatinHypercube };

struct Input {
  std::string name;
  std::string path;      ///< JSON path into the scenario, e.g. bodies[0].initial.speed
  std::string pointer;   ///< the same as a JSON pointer, /bodies/0/initial/speed
  Distribution distribution;
  double low = -1e300, high = 1e300;  ///< hard physical bounds: a sample outside is refused
};

/// P(output > above): the output is "BODY.QUANTITY" (e.g. "p406.delta_v").
struct Threshold {
  std::string output;
  double above = 0.0;
};

struct Spec {
  std::string file;            ///< the spec's path (messages)
  std::string scenario_file;   ///< the base scenario, absolute
  std::string scenario_text;   ///< its JSON text as read
  std::vector<Input> inputs;
  Design design = Design::kLatinHypercube;
  int samples = 100;
  std::uint64_t seed = 1;
  std::vector<Threshold> thresholds;
  std::uint64_t hash = 0;      ///< of the spec and the base scenario text: records carry it
};

/// Reads and validates a spec; refusals (InputError) name the spec file, the field and what was
/// expected: a bad path, a distribution parameter out of its domain, bounds that exclude the
/// distribution's support, an unknown design.
Spec LoadSpec(const std::string& path);

/// Spec hash as 16 hex digits.
std::string HashText(std::uint64_t hash);

}  // namespace dymesh::ensemble
