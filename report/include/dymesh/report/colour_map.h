#pragma once
#include <array>
#include <cstdint>
#include <cstdio>
#include <string>

#include "dymesh/io/rgb.h"

/// The crush colour map shared by the report's views and the PLY meshes: grey where a vertex has no
/// permanent crush, then pale yellow through orange and red to dark red at the largest crush.
namespace dymesh {

/// Colour of an uncrushed vertex.
inline constexpr Rgb kNoCrushColour{208, 208, 208};

/// Colour of a crush `fraction` of the scale's maximum: 0 (exactly) is grey, (0, 1] runs along the
/// ramp; values outside [0, 1] are clamped.
inline Rgb CrushColour(double fraction) {
  // ramp stops: pale yellow, amber, orange, red, dark red
  constexpr std::array<Rgb, 5> kStops = {Rgb{255, 240, 150}, Rgb{253, 190, 80}, Rgb{245, 120, 40},
                                         Rgb{210, 40, 30}, Rgb{120, 0, 10}};
  if (!(fraction > 0.0)) return kNoCrushColour;
  const double t = (fraction >= 1.0 ? 1.0 : fraction) * (kStops.size() - 1);
  const int i = t >= kStops.size() - 1 ? static_cast<int>(kStops.size()) - 2 : static_cast<int>(t);
  const double w = t - i;
  auto mix = [w](std::uint8_t a, std::uint8_t b) {
    return static_cast<std::uint8_t>(a + (static_cast<double>(b) - a) * w + 0.5);
  };
  return {mix(kStops[i].r, kStops[i + 1].r), mix(kStops[i].g, kStops[i + 1].g), mix(kStops[i].b, kStops[i + 1].b)};
}

/// CSS form "#rrggbb".
inline std::string CssColour(Rgb c) {
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", c.r, c.g, c.b);
  return text;
}

}  // namespace dymesh
