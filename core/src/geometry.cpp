#include "dymesh/core/geometry.h"

#include <algorithm>
#include <cmath>

namespace dymesh {

bool InsideTriangleCrossProduct(const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c,
                                const Vec3& n, double edge_tolerance) {
  // spec §2 InsidePolygonTest_CrossProd: q must be left of every edge seen along n
  const Vec3* corners[3] = {&a, &b, &c};
  for (int i = 0; i < 3; ++i) {
    const Vec3& p0 = *corners[i];
    const Vec3& p1 = *corners[(i + 1) % 3];
    const Vec3 edge = p1 - p0;
    const double side = edge.cross(q - p0).dot(n);
    // points on the edge (within the relative tolerance) count as inside
    if (side < -edge_tolerance * edge.squaredNorm() * n.norm()) return false;
  }
  return true;
}

Vec3 ClosestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  // the Voronoi region of p: a corner, an edge, or the face
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + (d1 / (d1 - d3)) * ab;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  // inside the face: barycentric projection (a degenerate triangle falls back to its corner a)
  const double sum = va + vb + vc;
  if (!(sum > 0.0)) return a;
  return a + (vb / sum) * ab + (vc / sum) * ac;
}

std::array<double, 3> ClampedBarycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  // each corner's weight: the area of the sub-triangle opposite it over the whole, signed along n
  const Vec3 n = TriangleCross(a, b, c);
  const double nn = n.squaredNorm();
  std::array<double, 3> w = {1.0 / 3, 1.0 / 3, 1.0 / 3};
  if (!(nn > 0.0)) return w;
  w = {(c - b).cross(p - b).dot(n) / nn, (a - c).cross(p - c).dot(n) / nn, (b - a).cross(p - a).dot(n) / nn};
  // clamped to the triangle
  double sum = 0.0;
  for (double& x : w) sum += (x = std::max(x, 0.0));
  if (!(sum > 0.0)) return {1.0 / 3, 1.0 / 3, 1.0 / 3};
  for (double& x : w) x /= sum;
  return w;
}

bool RayPlaneDistance(const Vec3& origin, const Vec3& dir, const Vec3& a, const Vec3& n, double* t) {
  // distance along dir to the plane through a with normal n
  const double denom = dir.dot(n);
  if (std::abs(denom) < 1e-12) return false;
  *t = (a - origin).dot(n) / denom;
  return true;
}

bool SegmentCrossesTriangle(const Vec3& origin, const Vec3& dir, double length, const Vec3& a, const Vec3& b,
                            const Vec3& c, double slack, double* t) {
  // plane crossing within the (slightly widened) segment, then the inside test at the crossing
  const Vec3 n = TriangleCross(a, b, c).normalized();
  if (!std::isfinite(n.x()) || !RayPlaneDistance(origin, dir, a, n, t)) return false;
  if (*t < -slack || *t > length + slack) return false;
  return InsideTriangleCrossProduct(origin + *t * dir, a, b, c, n);
}

bool CandidateCrossing(const Vec3& origin, const Vec3& dir, double t_min, double t_max, const Vec3& a, const Vec3& b,
                       const Vec3& c, const Vec3& n, bool proven_inside, double* t) {
  if (!RayPlaneDistance(origin, dir, a, n, t)) return false;
  if (*t < t_min || *t > t_max) return false;
  return proven_inside || InsideTriangleCrossProduct(origin + *t * dir, a, b, c, n);
}

Mat3 BodyToEarth(double roll, double pitch, double yaw) {
  // spec §8 Amtx: yaw about z, then pitch about y, then roll about x (SAE, z down)
  const double cf = std::cos(roll), sf = std::sin(roll);
  const double ct = std::cos(pitch), st = std::sin(pitch);
  const double cp = std::cos(yaw), sp = std::sin(yaw);
  Mat3 r;
  r << ct * cp, sf * st * cp - cf * sp, cf * st * cp + sf * sp,
       ct * sp, sf * st * sp + cf * cp, cf * st * sp - sf * cp,
       -st,     sf * ct,                cf * ct;
  return r;
}

Vec3 EulerRates(double roll, double pitch, const Vec3& w) {
  // kinematic equations of the roll-pitch-yaw sequence (singular at pitch = +-90 deg)
  const double cf = std::cos(roll), sf = std::sin(roll);
  const double ct = std::cos(pitch), tt = std::tan(pitch);
  return Vec3(w.x() + (w.y() * sf + w.z() * cf) * tt,
              w.y() * cf - w.z() * sf,
              (w.y() * sf + w.z() * cf) / ct);
}

}  // namespace dymesh
