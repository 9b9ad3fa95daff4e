#pragma once
#include <cstdint>

/// A vertex colour as the PLY writer stores it.
namespace dymesh {

/// An sRGB colour, 8 bits per channel.
struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
};

}  // namespace dymesh
