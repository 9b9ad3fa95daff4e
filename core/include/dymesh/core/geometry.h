#pragma once
#include <cmath>
#include <array>

#include <Eigen/Core>
#include <Eigen/Geometry>

/// Geometry helpers of the model: triangle normal and area, the cross-product inside test (spec §2),
/// ray-plane distance, and the roll-pitch-yaw direction-cosine matrix (spec §8).
namespace dymesh {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

/// Unnormalised triangle normal (a-b-c counter-clockwise seen from outside); its length is twice the area.
inline Vec3 TriangleCross(const Vec3& a, const Vec3& b, const Vec3& c) { return (b - a).cross(c - a); }

/// The part of `v` along a surface of unit normal `n` (v less its normal component).
inline Vec3 AlongSurface(const Vec3& v, const Vec3& n) { return v - v.dot(n) * n; }

/// The unit vector along v, scaled by its largest component first so that components of 1e200 or
/// 1e-200 neither overflow nor vanish; the zero vector for a zero (or non-finite) v.
inline Vec3 UnitAlong(const Vec3& v) {
  const double largest = v.cwiseAbs().maxCoeff();
  return largest > 0.0 && std::isfinite(largest) ? Vec3((v / largest).normalized()) : Vec3::Zero();
}

/// InsidePolygonTest_CrossProd (spec §2): q lies inside triangle abc (normal n) when it is on the
/// inner side of all three edges; points on an edge or vertex count as inside (relative tolerance
/// `edge_tolerance` of the edge length squared).
bool InsideTriangleCrossProduct(const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c,
                                const Vec3& n, double edge_tolerance = 1e-12);

/// Distance t along unit `dir` from `origin` to the plane of triangle (point a, unit normal n);
/// returns false when the ray is (nearly) parallel to the plane.
bool RayPlaneDistance(const Vec3& origin, const Vec3& dir, const Vec3& a, const Vec3& n, double* t);

/// Relative widening of the exact segment test (round-off of the plane distance), per metre + 1.
inline constexpr double kSegmentSlack = 1e-9;

/// The exact candidate test of the locators: the segment origin + t dir, t in [-slack, length + slack],
/// crosses the plane of triangle abc inside the triangle (cross-product test). Sets *t when true.
bool SegmentCrossesTriangle(const Vec3& origin, const Vec3& dir, double length, const Vec3& a, const Vec3& b,
                            const Vec3& c, double slack, double* t);

/// The exact candidate test of Location (spec §2), shared by the contact step and the benchmarks:
/// the ray origin + t dir meets the plane of triangle abc (unit normal n) at t in [t_min, t_max]
/// and, unless `proven_inside` (the locator showed it with margin), inside the triangle
/// (InsidePolygonTest_CrossProd). Sets *t when it meets the plane.
bool CandidateCrossing(const Vec3& origin, const Vec3& dir, double t_min, double t_max, const Vec3& a, const Vec3& b,
                       const Vec3& c, const Vec3& n, bool proven_inside, double* t);

/// Closest point of triangle abc to p (Ericson, Real-Time Collision Detection 5.1.5).
Vec3 ClosestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

/// Barycentric weights of p's projection on the plane of triangle abc, clamped to the triangle:
/// negative weights (p beyond an edge) set to zero and the rest rescaled to sum to 1; a degenerate
/// triangle gives 1/3 each.
std::array<double, 3> ClampedBarycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

/// Euler-angle DCM (spec §8, Amtx): maps body-frame vectors to the earth frame,
/// R = Rz(yaw) * Ry(pitch) * Rx(roll), SAE axes (x forward, y right, z down).
Mat3 BodyToEarth(double roll, double pitch, double yaw);

/// Euler-angle rates from body angular velocity (p, q, r) for the roll-pitch-yaw sequence.
Vec3 EulerRates(double roll, double pitch, const Vec3& body_rates);

}  // namespace dymesh
