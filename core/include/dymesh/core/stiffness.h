#pragma once
#include <array>
#include <cstdint>

#include "dymesh/core/geometry.h"

/// Per-area crush stiffness (spec §3, §4) and the body surfaces it is assigned to.
namespace dymesh {

/// Body surface of a vertex (BodySurface, DefineVertStiffness), SAE body axes.
enum class BodySurface : std::uint8_t { kFront, kRight, kBack, kLeft, kTop, kBottom };
inline constexpr int kBodySurfaceCount = 6;

/// Name of a surface as used in scenario files ("front", "right", ...).
const char* BodySurfaceName(BodySurface s);

/// 3-D (per-area) force-deflection coefficients of one surface, SI.
struct Stiffness {
  double A = 0.0;          ///< [N/m^2]  constant term (Stiffness[0])
  double B = 0.0;          ///< [N/m^3]  linear term
  double C = 0.0;          ///< [N/m^4]  quadratic term
  double D = 0.0;          ///< [N/m^5]  cubic term
  double sat_crush = 0.0;  ///< [m] SatCrush: force held constant beyond it (0 = no saturation)
  double max_crush = 0.0;  ///< [m] maximum crush a node can take (0 = unlimited)
  double unload_slope = 0.0;  ///< [N/m^3] Ku: unloading line slope per area (0 = not used)
};

/// Eq. 3 (spec §4): 3-D stiffness from published 2-D coefficients A [N/m], B [N/m^2]
/// and the conversion height H [m] of the crush region they were derived on.
Stiffness StiffnessFrom2D(double a_per_width, double b_per_width, double conversion_height);

/// Surface class of a vertex from its outward normal in the body frame (largest component).
BodySurface ClassifySurface(const Vec3& body_normal);

}  // namespace dymesh
