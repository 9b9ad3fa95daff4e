#pragma once
/// SI conversion factors for the US-customary inputs DyMESH users give (in, lbf, lb, mph).
namespace dymesh::units {

inline constexpr double kInch = 0.0254;                  ///< [m] per in
inline constexpr double kFoot = 0.3048;                  ///< [m] per ft
inline constexpr double kPoundForce = 4.4482216152605;   ///< [N] per lbf
inline constexpr double kPoundMass = 0.45359237;         ///< [kg] per lb (weight at standard g)
inline constexpr double kMph = 0.44704;                  ///< [m/s] per mph
inline constexpr double kStandardGravity = 9.80665;      ///< [m/s^2]
inline constexpr double kDegree = 3.14159265358979323846 / 180.0;  ///< [rad] per degree

/// Stiffness per area with exponent n: lb/in^n -> N/m^n (n = 1 for A per width, 2 for A per area, ...).
constexpr double PoundPerInchPow(int n) {
  double f = kPoundForce;
  for (int i = 0; i < n; ++i) f /= kInch;
  return f;
}

}  // namespace dymesh::units
