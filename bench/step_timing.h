#pragma once
// Cost of whole collision steps (all passes, forces, sums, refit) and of the raw ray casts inside them.
#include <cstdint>

#include "contact_setup.h"

namespace dymesh::bench {

/// Mean wall time of one collision step and of its passes' segments replayed as raw Embree rays.
struct StepTiming {
  double step_seconds = 0.0;     ///< [s] mean over the timed steps
  double raycast_seconds = 0.0;  ///< [s] raw rtcIntersect1 for one step's segments, same threads
  long long segments = 0;        ///< segments cast in that step
  std::uint64_t state_hash = 0;  ///< FNV-1a of both bodies' final vertex positions: equal at any thread count
};

/// Steps run before a mid-pulse timing: 20 ms at the 0.5 ms step, the slave 0.27 m further in (0.37 m
/// of closure in all), when most faces the nodes meet are crushed (the first steps meet undamaged ones).
inline constexpr int kMidPulseWarmup = 40;

/// Runs `warmup` steps into contact, times `steps` more with `threads` worker threads, then replays
/// one further step's segments as raw rays. The slave keeps closing at its set-up speed.
StepTiming MeasureSteps(const ContactSetup& setup, int threads, int warmup, int steps,
                        const ContactOptions& options = {});

}  // namespace dymesh::bench
