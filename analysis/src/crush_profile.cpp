#include "dymesh/analysis/crush_profile.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dymesh {
namespace {

// a vertex is damaged when its depth reaches this fraction of the face's largest depth
constexpr double kDamagedFraction = 0.05;
// below this largest depth a body counts as undamaged
constexpr double kMinimumCrush = 0.001;  // [m]
constexpr std::array<CrushFace, 4> kFaces = {CrushFace::kFront, CrushFace::kBack, CrushFace::kRight, CrushFace::kLeft};

// outward normal of a face, body axes
Vec3 OutwardNormal(CrushFace face) {
  switch (face) {
    case CrushFace::kFront: return Vec3(1, 0, 0);
    case CrushFace::kBack: return Vec3(-1, 0, 0);
    case CrushFace::kRight: return Vec3(0, 1, 0);
    case CrushFace::kLeft: return Vec3(0, -1, 0);
    case CrushFace::kNone: break;
  }
  return Vec3::Zero();
}

// coordinate along the damage width, increasing from C1 to C6: y across the front and back
// (left to right), -x along the sides (front to rear)
double WidthCoordinate(const Vec3& p, CrushFace face) {
  return face == CrushFace::kFront || face == CrushFace::kBack ? p.y() : -p.x();
}

// body-axis value of a width coordinate (undoes the sign of WidthCoordinate)
double BodyCoordinate(double s, CrushFace face) {
  return face == CrushFace::kFront || face == CrushFace::kBack ? s : -s;
}

// the face whose crush depths, summed over every vertex, are largest
CrushFace DamagedFace(const BodyState& state) {
  CrushFace best = CrushFace::kNone;
  double best_sum = 0.0;
  for (CrushFace face : kFaces) {
    double sum = 0.0;
    for (int v = 0; v < static_cast<int>(state.delta.size()); ++v) sum += CrushDepth(state, v, face);
    if (sum > best_sum) {
      best_sum = sum;
      best = face;
    }
  }
  return best;
}

// C at one station: the deepest vertex within half a spacing; if none lies there, the deepest of
// the vertices nearest to the station along the width
double StationCrush(const std::vector<double>& s, const std::vector<double>& depth, double station, double half) {
  double within = -1.0, nearest = std::numeric_limits<double>::infinity();
  for (std::size_t v = 0; v < s.size(); ++v) {
    const double distance = std::abs(s[v] - station);
    if (distance <= half) within = std::max(within, depth[v]);
    nearest = std::min(nearest, distance);
  }
  if (within >= 0.0) return within;
  double deepest = 0.0;
  const double tie = nearest + 1e-9 * (1.0 + nearest);
  for (std::size_t v = 0; v < s.size(); ++v)
    if (std::abs(s[v] - station) <= tie) deepest = std::max(deepest, depth[v]);
  return deepest;
}

}  // namespace

const char* CrushFaceName(CrushFace face) {
  switch (face) {
    case CrushFace::kFront: return "front";
    case CrushFace::kBack: return "back";
    case CrushFace::kRight: return "right";
    case CrushFace::kLeft: return "left";
    case CrushFace::kNone: break;
  }
  return "none";
}

double CrushDepth(const BodyState& state, int v, CrushFace face) {
  return std::max(0.0, -state.delta[v].dot(OutwardNormal(face)));
}

CrushProfile MeasureCrushProfile(const BodyModel& model, const BodyState& state) {
  CrushProfile profile;
  const CrushFace face = DamagedFace(state);
  if (face == CrushFace::kNone) return profile;
  // depth and width coordinate (undamaged position) of every vertex
  const int n = static_cast<int>(state.delta.size());
  std::vector<double> depth(n), s(n);
  for (int v = 0; v < n; ++v) {
    depth[v] = CrushDepth(state, v, face);
    s[v] = WidthCoordinate(model.mesh.vertices[v], face);
  }
  const double max_depth = *std::max_element(depth.begin(), depth.end());
  if (max_depth < kMinimumCrush) return profile;
  // damage width: extent of the damaged vertices
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (int v = 0; v < n; ++v) {
    if (depth[v] < kDamagedFraction * max_depth) continue;
    lo = std::min(lo, s[v]);
    hi = std::max(hi, s[v]);
  }
  profile.face = face;
  profile.max_depth = max_depth;
  profile.width = hi - lo;
  profile.centre = BodyCoordinate(0.5 * (lo + hi), face);
  // six stations, ends included, C1 first
  const double spacing = profile.width / 5.0;
  for (int i = 0; i < 6; ++i) {
    const double station = lo + i * spacing;
    profile.station[i] = BodyCoordinate(station, face);
    profile.crush[i] = StationCrush(s, depth, station, 0.5 * spacing);
  }
  return profile;
}

}  // namespace dymesh
