#pragma once
#include <vector>

#include "dymesh/ensemble/spec.h"

/// The design: which uniform numbers each sample gets, and the input values they give.
namespace dymesh::ensemble {

/// The samples' uniform numbers for a spec, one row per sample and one column per input: a pure
/// function of (spec hash, seed, input name, sample index) for Monte Carlo; Latin hypercube
/// stratifies each input into `samples` equal-probability strata visited in a permutation drawn
/// from the same streams; correlated inputs are then re-paired (Iman-Conover) so that they keep
/// their strata and carry the copula's rank correlation.
class DesignTable {
 public:
  explicit DesignTable(const Spec& spec);
  /// Sample i's input values (spec units), each checked against its bounds by the caller.
  std::vector<double> Values(int sample) const;

 private:
  std::vector<double> Deterministic(int sample) const;  // grid and one-at-a-time
  void InduceRankCorrelation();                          // Latin hypercube with a correlation
  const Spec& spec_;
  std::vector<std::vector<int>> strata_;  // Latin hypercube: stratum of each sample, per input
};

}  // namespace dymesh::ensemble
