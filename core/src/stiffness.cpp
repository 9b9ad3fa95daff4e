#include "dymesh/core/stiffness.h"

#include <cmath>

namespace dymesh {

const char* BodySurfaceName(BodySurface s) {
  static constexpr const char* kNames[kBodySurfaceCount] = {"front", "right", "back", "left", "top", "bottom"};
  return kNames[static_cast<int>(s)];
}

Stiffness StiffnessFrom2D(double a_per_width, double b_per_width, double conversion_height) {
  // spec §4 Eq. 3: per-area coefficients are the per-width ones over the conversion height
  Stiffness k;
  k.A = a_per_width / conversion_height;
  k.B = b_per_width / conversion_height;
  return k;
}

BodySurface ClassifySurface(const Vec3& n) {
  // the dominant axis of the outward normal picks the surface (SAE: +x front, +y right, -z top)
  const double ax = std::abs(n.x()), ay = std::abs(n.y()), az = std::abs(n.z());
  if (ax >= ay && ax >= az) return n.x() >= 0 ? BodySurface::kFront : BodySurface::kBack;
  if (ay >= az) return n.y() >= 0 ? BodySurface::kRight : BodySurface::kLeft;
  return n.z() <= 0 ? BodySurface::kTop : BodySurface::kBottom;
}

}  // namespace dymesh
