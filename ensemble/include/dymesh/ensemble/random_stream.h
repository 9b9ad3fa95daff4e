#pragma once
#include <cstdint>
#include <string>

/// Counter-based uniform numbers (Random123 Philox4x32-10): a draw is a pure function of the seed,
/// the input's name and the sample index, so samples can run in any order, on any thread or rank,
/// and adding an input (or changing another) does not shift an input's stream.
namespace dymesh::ensemble {

/// 64-bit FNV-1a of a text (input names, spec text).
std::uint64_t TextHash(const std::string& text);

/// A uniform number in (0, 1) for draw `draw` of sample `sample` of the stream named by `stream`.
double Uniform(std::uint64_t seed, std::uint64_t stream, std::uint64_t sample, std::uint32_t draw = 0);

}  // namespace dymesh::ensemble
