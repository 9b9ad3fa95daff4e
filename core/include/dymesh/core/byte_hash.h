#pragma once
#include <cstddef>
#include <cstdint>

/// 64-bit FNV-1a over bytes: the one hash behind the final-state hashes (determinism tests, the step
/// benchmark, the C API's dm_world_state_hash) and the ensemble's stream and spec hashes.
namespace dymesh {

/// FNV-1a's offset basis: the hash of no bytes.
inline constexpr std::uint64_t kFnv1aBasis = 1469598103934665603ull;

/// `hash` continued over the `size` bytes at `data`.
inline std::uint64_t Fnv1a(const void* data, std::size_t size, std::uint64_t hash = kFnv1aBasis) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * 1099511628211ull;
  return hash;
}

}  // namespace dymesh
