#pragma once
#include <pmmintrin.h>
#include <xmmintrin.h>

#include <algorithm>
#include <cstddef>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>

/// The one parallel shim (oneTBB): fixed-size chunks, so results never depend on the thread count.
namespace dymesh {

/// Size of every chunk of a chunked loop; chunk boundaries depend only on the loop length.
inline constexpr std::size_t kChunkSize = 256;

/// Number of chunks of a loop over n items.
inline std::size_t ChunkCount(std::size_t n) { return (n + kChunkSize - 1) / kChunkSize; }

/// Flush-to-zero and denormals-are-zero on for its scope, restored after: every thread that computes
/// model quantities runs with the same floating-point mode.
class FloatModeScope {
 public:
  FloatModeScope() : saved_(_mm_getcsr()) { _mm_setcsr(saved_ | _MM_FLUSH_ZERO_ON | _MM_DENORMALS_ZERO_ON); }
  ~FloatModeScope() { _mm_setcsr(saved_); }
  FloatModeScope(const FloatModeScope&) = delete;
  FloatModeScope& operator=(const FloatModeScope&) = delete;

 private:
  unsigned saved_;
};

/// Calls body(chunk, begin, end) for every fixed-size chunk of [0, n).
/// Threading: chunks run concurrently on oneTBB workers. Determinism: a chunk writes only its own
/// slots; callers fold per-chunk results serially in chunk order.
template <class Body>
void ForEachChunk(std::size_t n, Body&& body) {
  const std::size_t chunks = ChunkCount(n);
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, chunks, 1),
      [&](const tbb::blocked_range<std::size_t>& range) {
        FloatModeScope float_mode;
        for (std::size_t c = range.begin(); c != range.end(); ++c) {
          body(c, c * kChunkSize, std::min(n, (c + 1) * kChunkSize));
        }
      },
      tbb::simple_partitioner());
}

}  // namespace dymesh
