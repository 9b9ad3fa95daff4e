#pragma once
#include <cstdint>

/// Sobol' low-discrepancy points (Joe and Kuo's direction numbers, up to 16 dimensions), each
/// dimension scrambled by a random digital shift: the net structure stays, the points become an
/// unbiased randomized quasi-Monte Carlo sample.
namespace dymesh::ensemble {

/// Dimensions available.
inline constexpr int kSobolDimensions = 16;

/// Coordinate `dimension` (0-based) of point `index` of the unshifted sequence (natural order: the
/// XOR of the direction numbers of the index's set bits; every block of 2^m points is the same net
/// as in Gray-code order), in [0, 1).
double SobolCoordinate(std::uint64_t index, int dimension);

/// The same point digitally shifted by `shift` (XOR of the 32-bit fraction), in (0, 1).
double ShiftedSobolCoordinate(std::uint64_t index, int dimension, std::uint32_t shift);

}  // namespace dymesh::ensemble
