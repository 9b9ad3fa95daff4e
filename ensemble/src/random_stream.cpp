#include "dymesh/ensemble/random_stream.h"

#include <Random123/philox.h>

#include "dymesh/core/byte_hash.h"

namespace dymesh::ensemble {

std::uint64_t TextHash(const std::string& text) { return Fnv1a(text.data(), text.size()); }

double Uniform(std::uint64_t seed, std::uint64_t stream, std::uint64_t sample, std::uint32_t draw) {
  // key: the seed; counter: the stream (input), the sample and the draw
  const std::uint64_t key64 = seed * 0x9E3779B97F4A7C15ull + 0x2545F4914F6CDD1Dull;
  r123::Philox4x32::key_type key = {{static_cast<std::uint32_t>(key64), static_cast<std::uint32_t>(key64 >> 32)}};
  r123::Philox4x32::ctr_type ctr = {{static_cast<std::uint32_t>(sample), static_cast<std::uint32_t>(sample >> 32),
                                     static_cast<std::uint32_t>(stream ^ (stream >> 32)), draw}};
  const r123::Philox4x32::ctr_type out = r123::Philox4x32()(ctr, key);
  // 53 random bits, shifted off 0 and 1
  const std::uint64_t bits = (static_cast<std::uint64_t>(out[0]) << 21) ^ static_cast<std::uint64_t>(out[1] >> 11);
  return (static_cast<double>(bits & ((1ull << 53) - 1)) + 0.5) / 9007199254740992.0;
}

}  // namespace dymesh::ensemble
