#include "dymesh/ensemble/design.h"

#include <algorithm>
#include <numeric>

#include "dymesh/ensemble/random_stream.h"

namespace dymesh::ensemble {

DesignTable::DesignTable(const Spec& spec) : spec_(spec) {
  if (spec.design != Design::kLatinHypercube) return;
  // per input, the samples ordered by a random key of their own: sample j takes stratum rank(j)
  for (const Input& in : spec.inputs) {
    const std::uint64_t stream = TextHash(in.name);
    std::vector<std::pair<double, int>> keys(spec.samples);
    for (int j = 0; j < spec.samples; ++j) keys[j] = {Uniform(spec.seed, stream, j, 1), j};
    std::sort(keys.begin(), keys.end());
    std::vector<int> stratum(spec.samples);
    for (int rank = 0; rank < spec.samples; ++rank) stratum[keys[rank].second] = rank;
    strata_.push_back(std::move(stratum));
  }
}

std::vector<double> DesignTable::Values(int sample) const {
  std::vector<double> values;
  for (std::size_t k = 0; k < spec_.inputs.size(); ++k) {
    const Input& in = spec_.inputs[k];
    double u = Uniform(spec_.seed, TextHash(in.name), sample, 0);
    // Latin hypercube: the draw placed inside the sample's stratum
    if (spec_.design == Design::kLatinHypercube) u = (strata_[k][sample] + u) / spec_.samples;
    values.push_back(Quantile(in.distribution, u));
  }
  return values;
}

}  // namespace dymesh::ensemble
