#include "dymesh/ensemble/sobol_sequence.h"

#include <array>
#include <stdexcept>
#include <vector>

namespace dymesh::ensemble {
namespace {

// Joe and Kuo (new-joe-kuo-6.21201), dimensions 2..16: degree s, polynomial a, initial m_1..m_s
struct Primitive {
  int s, a;
  std::array<std::uint32_t, 6> m;
};
constexpr std::array<Primitive, kSobolDimensions - 1> kPrimitives = {{
    {1, 0, {1}}, {2, 1, {1, 3}}, {3, 1, {1, 3, 1}}, {3, 2, {1, 1, 1}}, {4, 1, {1, 1, 3, 3}},
    {4, 4, {1, 3, 5, 13}}, {5, 2, {1, 1, 5, 5, 17}}, {5, 4, {1, 1, 5, 5, 5}}, {5, 7, {1, 1, 7, 11, 19}},
    {5, 11, {1, 1, 5, 1, 1}}, {5, 13, {1, 1, 1, 3, 11}}, {5, 14, {1, 3, 5, 5, 31}},
    {6, 1, {1, 3, 3, 9, 7, 49}}, {6, 13, {1, 1, 1, 15, 21, 21}}, {6, 16, {1, 3, 1, 13, 27, 49}},
}};

constexpr int kBits = 32;

// the direction numbers v_1..v_32 of one dimension (scaled by 2^32)
std::array<std::uint32_t, kBits> Directions(int dimension) {
  std::array<std::uint32_t, kBits> v{};
  if (dimension == 0) {
    for (int k = 0; k < kBits; ++k) v[k] = 1u << (kBits - 1 - k);
    return v;
  }
  const Primitive& p = kPrimitives[dimension - 1];
  for (int k = 0; k < p.s; ++k) v[k] = p.m[k] << (kBits - 1 - k);
  for (int k = p.s; k < kBits; ++k) {
    v[k] = v[k - p.s] ^ (v[k - p.s] >> p.s);
    for (int j = 1; j < p.s; ++j)
      if ((p.a >> (p.s - 1 - j)) & 1u) v[k] ^= v[k - j];
  }
  return v;
}

// all dimensions' direction numbers, made once
const std::vector<std::array<std::uint32_t, kBits>>& Table() {
  static const std::vector<std::array<std::uint32_t, kBits>> table = [] {
    std::vector<std::array<std::uint32_t, kBits>> t;
    for (int d = 0; d < kSobolDimensions; ++d) t.push_back(Directions(d));
    return t;
  }();
  return table;
}

// the 32-bit fraction of point `index` (direct Gray-code-free construction: XOR of the directions
// of the set bits of the index)
std::uint32_t Bits(std::uint64_t index, int dimension) {
  if (dimension < 0 || dimension >= kSobolDimensions) throw std::out_of_range("Sobol' dimension");
  const auto& v = Table()[dimension];
  std::uint32_t x = 0;
  for (int k = 0; k < kBits && index != 0; ++k, index >>= 1)
    if (index & 1u) x ^= v[k];
  return x;
}

std::uint32_t ReverseBits(std::uint32_t x) {
  x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  x = ((x >> 4) & 0x0F0F0F0Fu) | ((x & 0x0F0F0F0Fu) << 4);
  x = ((x >> 8) & 0x00FF00FFu) | ((x & 0x00FF00FFu) << 8);
  return (x >> 16) | (x << 16);
}

// Burley's Laine-Karras hash: adding the seed and XOR-ing products with even constants changes each
// bit only as a function of the bits below it, so on reversed digits it is a nested scramble
std::uint32_t LaineKarras(std::uint32_t x, std::uint32_t seed) {
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return x;
}

}  // namespace

double SobolCoordinate(std::uint64_t index, int dimension) { return Bits(index, dimension) / 4294967296.0; }

double ScrambledSobolCoordinate(std::uint64_t index, int dimension, std::uint32_t seed) {
  // digit k of the fraction is bit k of the reversed word: the hash flips it by the digits before it
  const std::uint32_t scrambled = ReverseBits(LaineKarras(ReverseBits(Bits(index, dimension)), seed));
  return (scrambled + 0.5) / 4294967296.0;
}

}  // namespace dymesh::ensemble
