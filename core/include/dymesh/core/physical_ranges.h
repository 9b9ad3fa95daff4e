#pragma once

/// The ranges a scenario's values may take (README "Physical ranges"), SI: beyond the hard bounds a
/// value is impossible and refused; beyond the plausible ones it is accepted with a warning naming
/// the field. One table for a scenario file (io, messages in the file's units) and a world built
/// from arrays (the C ABI, SI).
namespace dymesh {

struct PhysicalRange {
  double hard_lo, hard_hi, lo, hi;
  const char* what;  // the quantity, for messages
};

inline constexpr double kSpeedOfSound = 343.0;  // [m/s]
inline constexpr PhysicalRange kSpeedRange{-kSpeedOfSound, kSpeedOfSound, -67.0, 67.0, "speed"};  // plausible: 150 mph
inline constexpr PhysicalRange kYawRateRange{-36000.0, 36000.0, -720.0, 720.0, "yaw rate [deg/s]"};
inline constexpr PhysicalRange kHeadingRange{-720.0, 720.0, -360.0, 360.0, "heading [deg]"};
inline constexpr PhysicalRange kTiltRange{-180.0, 180.0, -45.0, 45.0, "roll or pitch [deg]"};
inline constexpr PhysicalRange kMassRange{1.0, 1e7, 50.0, 60000.0, "mass"};
inline constexpr PhysicalRange kPositionRange{-1e5, 1e5, -1e4, 1e4, "position coordinate"};  // [m]
inline constexpr PhysicalRange kCgRange{-100.0, 100.0, -20.0, 20.0, "CG coordinate"};        // [m] from the mesh origin
/// A body's largest extent [m]: a generated box's or cylinder's sizes as given (io), a mesh file's
/// largest built extent (CheckRunStart), a mesh given as arrays (the C ABI).
inline constexpr PhysicalRange kBodySizeRange{1e-3, 1000.0, 0.01, 30.0, "body size"};
inline constexpr PhysicalRange kGyrationRange{0.01, 100.0, 0.1, 15.0, "radius of gyration sqrt(inertia / mass)"};  // [m]
inline constexpr PhysicalRange kFrictionRange{0.0, 10.0, 0.0, 1.5, "friction coefficient"};
inline constexpr PhysicalRange kDurationRange{0.0, 1e4, 0.0, 10.0, "duration [s]"};
inline constexpr PhysicalRange kGapRange{0.0, 1e3, 0.0, 10.0, "gap"};  // [m] between bodies placed at contact
// 3-D stiffness (SI): published A up to ~1000 lb/in and B up to ~1000 lb/in^2 over a 30 in
// conversion height are ~2.3e5 N/m^2 and ~9e6 N/m^3; rigid-wall stand-ins go higher
inline constexpr PhysicalRange kStiffnessARange{0.0, 1e15, 0.0, 1e7, "3-D stiffness A [N/m^2]"};
inline constexpr PhysicalRange kStiffnessBRange{0.0, 1e15, 0.0, 1e9, "3-D stiffness B [N/m^3]"};
// the rebound slope Ku: steeper than loading, within the same order of reach
inline constexpr PhysicalRange kUnloadSlopeRange{0.0, 1e16, 0.0, 1e10, "unloading slope Kv [N/m^3]"};
// 2-D coefficients are spread over a height of structure: CRASH3 uses 10-40 in
inline constexpr PhysicalRange kConversionHeightRange{0.01, 10.0, 0.1, 2.0, "conversion height"};  // [m]

/// The most steps (duration / step) a run may ask for.
inline constexpr double kMaxSteps = 1e7;

}  // namespace dymesh
