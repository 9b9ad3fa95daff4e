#pragma once
#include <array>

#include "dymesh/core/body.h"

/// CRASH3-style six-point crush (C1..C6) measured on a body's permanent deformation.
///
/// Definition (also in the README):
/// - crush depth of a vertex on a face: its permanent deformation Delta projected on the face's
///   inward normal, max(0, -Delta . n_out) (front n_out = +x, back -x, right +y, left -y, body axes);
/// - damaged face: of front, back, right and left, the one whose crush depths summed over all
///   vertices are largest;
/// - damaged vertices: crush depth at least 5 % of the face's largest (and the largest at least 1 mm);
/// - damage width L: extent of the damaged vertices along the face (y for front and back, x for
///   the sides), undamaged positions;
/// - stations: six, equally spaced over L, ends included; C1 at the left for the front and back
///   (-y, the driver's side of a left-hand-drive car), at the front for the sides (+x);
/// - C_i: the largest crush depth among the vertices within half a station spacing of station i
///   (any height); if none lies there, the largest among the vertices nearest to the station along L.
namespace dymesh {

/// A face of the body (plan view).
enum class CrushFace { kNone, kFront, kBack, kRight, kLeft };

/// Name of a face: "none", "front", "back", "right", "left".
const char* CrushFaceName(CrushFace face);

/// Six-point crush profile of one body (all lengths SI, body axes about the CG).
struct CrushProfile {
  CrushFace face = CrushFace::kNone;  ///< kNone when the body has less than 1 mm of crush
  double width = 0.0;                 ///< [m] damage width L
  double centre = 0.0;                ///< [m] centre of the damage width on the width axis (y or x)
  std::array<double, 6> station{};    ///< [m] station coordinates on the width axis, C1 first
  std::array<double, 6> crush{};      ///< [m] C1..C6
  double max_depth = 0.0;             ///< [m] largest crush depth on the face
};

/// Crush depth of vertex v normal to `face` (0 for kNone): max(0, -Delta . n_out).
double CrushDepth(const BodyState& state, int v, CrushFace face);

/// Measures the six-point profile from the body's permanent deformation (see the definition above).
CrushProfile MeasureCrushProfile(const BodyModel& model, const BodyState& state);

}  // namespace dymesh
