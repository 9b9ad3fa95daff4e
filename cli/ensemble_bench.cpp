// `dymesh bench --ensemble SPEC`: samples per second at 1 and N threads, and memory per concurrent
// sample, for an ensemble spec (meshes loaded once and not timed).
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "bench_command.h"
#include "contact_setup.h"
#include "dymesh/ensemble/design.h"
#include "dymesh/ensemble/sample_run.h"
#include "dymesh/io/body_models.h"

namespace dymesh::cli {
namespace {

// wall seconds of `samples` samples from `first` on at most `threads` threads
double TimeSamples(const ensemble::Spec& spec, const ensemble::DesignTable& design, ensemble::SharedAssets* assets,
                   int first, int samples, int threads) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  const auto start = std::chrono::steady_clock::now();
  tbb::parallel_for(first, first + samples, [&](int i) { ensemble::RunSample(spec, i % spec.samples, design.Values(i % spec.samples), assets); });
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int RunEnsembleBench(const BenchRequest& request) {
  const ensemble::Spec spec = ensemble::LoadSpec(request.ensemble);
  const ensemble::DesignTable design(spec);
  ensemble::SharedAssets assets;
  // warm-up: the meshes load once (as in an ensemble run), not timed
  ensemble::RunSample(spec, 0, design.Values(0), &assets);
  const int n = request.samples;
  const double one = TimeSamples(spec, design, &assets, 1, n, 1);
  const double many = TimeSamples(spec, design, &assets, 1, n, request.threads);  // the same samples
  // memory a sample holds while it runs: its body models, states and Embree scenes
  const Scenario scenario = ensemble::SampleScenario(spec, design.Values(0));
  std::size_t bytes = 0;
  for (const auto& model : ensemble::SampleModels(scenario, &assets)) bytes += bench::MeasureBodyMemory(*model).total();
  const nlohmann::json j = {{"spec", request.ensemble}, {"samples_timed", n}, {"threads", request.threads},
                            {"samples_per_second", {{"threads_1", n / one}, {"threads_n", n / many}}},
                            {"seconds_per_sample", {{"threads_1", one / n}, {"threads_n", many / n}}},
                            {"speedup", one / many}, {"bytes_per_concurrent_sample", bytes},
                            {"seconds_per_1000_samples_at_n", 1000.0 * many / n}};
  if (request.json) {
    std::printf("%s\n", j.dump(2).c_str());
    return 0;
  }
  std::printf("%s: %d samples timed per setting\n", request.ensemble.c_str(), n);
  std::printf("  1 thread    %8.3f samples/s  (%.3f s per sample)\n", n / one, one / n);
  std::printf("  %d threads   %8.3f samples/s  (%.3f s per sample; %.2fx)\n", request.threads, n / many, many / n, one / many);
  std::printf("  1000 samples at %d threads: %.0f s; memory per concurrent sample %.1f MB\n", request.threads,
              1000.0 * many / n, bytes / 1e6);
  return 0;
}

}  // namespace dymesh::cli
