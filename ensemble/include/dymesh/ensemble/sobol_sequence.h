#pragma once
#include <cstdint>

/// Sobol' low-discrepancy points (Joe and Kuo's direction numbers, up to 16 dimensions), each
/// dimension Owen-scrambled (a nested uniform scramble, hashed after Burley 2020): the net structure
/// stays, every point is uniform, and the points become a randomized quasi-Monte Carlo sample.
namespace dymesh::ensemble {

/// Dimensions available.
inline constexpr int kSobolDimensions = 16;

/// Coordinate `dimension` (0-based) of point `index` of the unshifted sequence (natural order: the
/// XOR of the direction numbers of the index's set bits; every block of 2^m points is the same net
/// as in Gray-code order), in [0, 1).
double SobolCoordinate(std::uint64_t index, int dimension);

/// The same coordinate Owen-scrambled with `seed`: each binary digit flipped by a hash of the digits
/// above it (the Laine-Karras permutation on the reversed bits), in (0, 1).
double ScrambledSobolCoordinate(std::uint64_t index, int dimension, std::uint32_t seed);

}  // namespace dymesh::ensemble
