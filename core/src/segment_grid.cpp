#include "segment_grid.h"

#include <algorithm>
#include <cmath>

#include "dymesh/core/geometry.h"

namespace dymesh {

SegmentGrid::SegmentGrid(const TriMesh& mesh) : mesh_(mesh) {
  const PointBounds bounds = BoundsOf(mesh.vertices);
  lo_ = bounds.lo;
  hi_ = bounds.hi;
  // about one triangle per cell of the bounds (a flat body: cells of its area)
  const Vec3 size = (hi_ - lo_).cwiseMax(1e-9);
  const double count = static_cast<double>(std::max<std::size_t>(1, mesh.triangles.size()));
  const Vec3 sorted = [&] { Vec3 s = size; std::sort(s.data(), s.data() + 3); return s; }();
  cell_ = std::max(std::cbrt(size.prod() / count), std::sqrt(sorted[1] * sorted[2] / count));
  for (int k = 0; k < 3; ++k) dims_[k] = static_cast<int>(size[k] / cell_) + 1;
  off_plane_ = kSegmentSlack * (1.0 + size.norm());
  // triangles into every cell their bounds touch: counted, then placed (cell-major)
  const std::size_t cells = static_cast<std::size_t>(dims_[0]) * dims_[1] * dims_[2];
  auto each_cell = [&](int t, auto&& visit) {
    const auto& tri = mesh.triangles[t];
    Vec3 a = mesh.vertices[tri[0]], b = a;
    for (int k = 1; k < 3; ++k) {
      a = a.cwiseMin(mesh.vertices[tri[k]]);
      b = b.cwiseMax(mesh.vertices[tri[k]]);
    }
    const std::array<int, 3> c0 = CellOf(a), c1 = CellOf(b);
    for (int z = c0[2]; z <= c1[2]; ++z)
      for (int y = c0[1]; y <= c1[1]; ++y)
        for (int x = c0[0]; x <= c1[0]; ++x) visit((static_cast<std::size_t>(z) * dims_[1] + y) * dims_[0] + x);
  };
  first_.assign(cells + 1, 0);
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) each_cell(t, [&](std::size_t c) { ++first_[c + 1]; });
  for (std::size_t c = 0; c < cells; ++c) first_[c + 1] += first_[c];
  ids_.resize(first_.back());
  std::vector<int> fill(first_.begin(), first_.end() - 1);
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) each_cell(t, [&](std::size_t c) { ids_[fill[c]++] = t; });
}

std::array<int, 3> SegmentGrid::CellOf(const Vec3& p) const {
  std::array<int, 3> c;
  for (int k = 0; k < 3; ++k)
    c[k] = std::clamp(static_cast<int>(std::floor((p[k] - lo_[k]) / cell_)), 0, dims_[k] - 1);
  return c;
}

void SegmentGrid::CandidatesAlong(const Vec3& p0, const Vec3& p1, std::vector<int>* out) const {
  // the part of the segment within the grid (a cell of margin): a long edge passing a fine body
  // steps only across the body
  double t0 = 0.0, t1 = 1.0;
  const Vec3 d = p1 - p0;
  for (int k = 0; k < 3; ++k) {
    const double lo = lo_[k] - cell_, hi = hi_[k] + cell_;
    if (d[k] == 0.0) {
      if (p0[k] < lo || p0[k] > hi) return;
      continue;
    }
    const double a = (lo - p0[k]) / d[k], b = (hi - p0[k]) / d[k];
    t0 = std::max(t0, std::min(a, b));
    t1 = std::min(t1, std::max(a, b));
  }
  if (t0 > t1) return;
  // the cells round points half a cell apart along it (every cell it passes is within one cell of
  // such a point), each triangle once
  const int steps = static_cast<int>(std::ceil(2.0 * (t1 - t0) * d.norm() / cell_)) + 1;
  for (int i = 0; i <= steps; ++i) {
    const std::array<int, 3> c = CellOf(p0 + (t0 + (t1 - t0) * i / steps) * d);
    for (int z = std::max(c[2] - 1, 0); z <= std::min(c[2] + 1, dims_[2] - 1); ++z)
      for (int y = std::max(c[1] - 1, 0); y <= std::min(c[1] + 1, dims_[1] - 1); ++y)
        for (int x = std::max(c[0] - 1, 0); x <= std::min(c[0] + 1, dims_[0] - 1); ++x) {
          const std::size_t cell = (static_cast<std::size_t>(z) * dims_[1] + y) * dims_[0] + x;
          out->insert(out->end(), ids_.begin() + first_[cell], ids_.begin() + first_[cell + 1]);
        }
  }
  std::sort(out->begin(), out->end());
  out->erase(std::unique(out->begin(), out->end()), out->end());
}

std::vector<double> SegmentGrid::Crossings(const Vec3& p0, const Vec3& p1) const {
  std::vector<double> crossings;
  std::vector<int> candidates;
  CandidatesAlong(p0, p1, &candidates);
  for (int t : candidates) {
    const auto& tri = mesh_.triangles[t];
    const Vec3 &u = mesh_.vertices[tri[0]], &v = mesh_.vertices[tri[1]], &w = mesh_.vertices[tri[2]];
    const Vec3 n = TriangleCross(u, v, w).normalized();
    if (!n.allFinite()) continue;
    // from one side of the plane to the other, then inside the triangle where it crosses
    const double d0 = (p0 - u).dot(n), d1 = (p1 - u).dot(n);
    if (d0 * d1 >= 0.0 || std::min(std::abs(d0), std::abs(d1)) <= off_plane_) continue;
    const double s = d0 / (d0 - d1);
    if (InsideTriangleCrossProduct(p0 + s * (p1 - p0), u, v, w, n)) crossings.push_back(s);
  }
  std::sort(crossings.begin(), crossings.end());
  return crossings;
}

}  // namespace dymesh
