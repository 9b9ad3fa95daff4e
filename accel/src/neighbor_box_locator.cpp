#include "dymesh/accel/neighbor_box_locator.h"

#include <algorithm>
#include <cmath>

#include "dymesh/core/geometry.h"
#include "dymesh/core/parallel.h"
#include "dymesh/core/units.h"

namespace dymesh::accel {
namespace {

// SetBoxSize: the box is this fraction of the body's largest extent, with at least this much slack
// beyond the search segment
constexpr double kBoxFraction = 0.05;
constexpr double kMinSlack = 1.0 * units::kInch;  // [m]

double MaxAbs(const Vec3& v) { return v.cwiseAbs().maxCoeff(); }

}  // namespace

NeighborBoxLocator::NeighborBoxLocator(const TriMesh& mesh, const ContactOptions& options)
    : triangles_(mesh.triangles), vertices_(mesh.vertices), interval_(options.calc_nabor_interval) {
  // GLOBAL_SEARCH_BOX: given, or SetBoxSize from the extents; never smaller than the search segment
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  for (const Vec3& p : mesh.vertices) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double search = std::max(options.search_backoff, options.toofar_maximum) * (1.0 + 1e-6);
  const double wanted = options.global_search_box > 0.0 ? options.global_search_box
                                                         : kBoxFraction * (hi - lo).maxCoeff();
  half_size_ = std::max(wanted, search + kMinSlack);
  slack_ = half_size_ - search;
}

void NeighborBoxLocator::Update(const std::vector<Vec3>& vertices, const std::vector<int>& moved) {
  // track how far the master moved since the grid was built (lists stay valid within the slack)
  for (int v : moved) {
    vertices_[v] = vertices[v];
    if (!grid_vertices_.empty()) master_drift_ = std::max(master_drift_, MaxAbs(vertices_[v] - grid_vertices_[v]));
  }
}

void NeighborBoxLocator::BuildGrid() {
  // triangle bounds binned into cells one box half-size wide
  const size_t nt = triangles_.size();
  tri_min_.resize(nt);
  tri_max_.resize(nt);
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  for (size_t t = 0; t < nt; ++t) {
    const Vec3& a = vertices_[triangles_[t][0]];
    const Vec3& b = vertices_[triangles_[t][1]];
    const Vec3& c = vertices_[triangles_[t][2]];
    tri_min_[t] = a.cwiseMin(b).cwiseMin(c);
    tri_max_[t] = a.cwiseMax(b).cwiseMax(c);
    lo = lo.cwiseMin(tri_min_[t]);
    hi = hi.cwiseMax(tri_max_[t]);
  }
  grid_origin_ = lo;
  for (int k = 0; k < 3; ++k) grid_dims_[k] = std::max(1, static_cast<int>(std::ceil((hi[k] - lo[k]) / half_size_)));
  cells_.assign(static_cast<size_t>(grid_dims_[0]) * grid_dims_[1] * grid_dims_[2], {});
  auto cell = [&](const Vec3& p, int k) {
    return std::clamp(static_cast<int>((p[k] - grid_origin_[k]) / half_size_), 0, grid_dims_[k] - 1);
  };
  for (size_t t = 0; t < nt; ++t) {
    for (int i = cell(tri_min_[t], 0); i <= cell(tri_max_[t], 0); ++i)
      for (int j = cell(tri_min_[t], 1); j <= cell(tri_max_[t], 1); ++j)
        for (int k = cell(tri_min_[t], 2); k <= cell(tri_max_[t], 2); ++k)
          cells_[(static_cast<size_t>(i) * grid_dims_[1] + j) * grid_dims_[2] + k].push_back(static_cast<int>(t));
  }
  grid_vertices_ = vertices_;
  master_drift_ = 0.0;
}

void NeighborBoxLocator::BuildList(const Vec3& p, NaborList* list) const {
  // NaborSurf: every triangle whose bounds meet the box around p, ascending
  list->surfaces.clear();
  const Vec3 lo = p.array() - half_size_, hi = p.array() + half_size_;
  std::array<int, 3> c0, c1;
  for (int k = 0; k < 3; ++k) {
    c0[k] = static_cast<int>(std::floor((lo[k] - grid_origin_[k]) / half_size_));
    c1[k] = static_cast<int>(std::floor((hi[k] - grid_origin_[k]) / half_size_));
    c0[k] = std::max(c0[k], 0);
    c1[k] = std::min(c1[k], grid_dims_[k] - 1);
    if (c0[k] > c1[k]) return;  // the box misses the master
  }
  for (int i = c0[0]; i <= c1[0]; ++i)
    for (int j = c0[1]; j <= c1[1]; ++j)
      for (int k = c0[2]; k <= c1[2]; ++k)
        for (int t : cells_[(static_cast<size_t>(i) * grid_dims_[1] + j) * grid_dims_[2] + k]) {
          if ((tri_min_[t].array() <= hi.array()).all() && (tri_max_[t].array() >= lo.array()).all()) {
            list->surfaces.push_back(t);
          }
        }
  std::sort(list->surfaces.begin(), list->surfaces.end());
  list->surfaces.erase(std::unique(list->surfaces.begin(), list->surfaces.end()), list->surfaces.end());
}

void NeighborBoxLocator::Prepare(int slave_body, int step, const std::vector<int>& keys,
                                 const std::function<Vec3(int)>& position) {
  // CALC_NABOR_INTERVAL: the grid and every list are rebuilt on schedule, or when the master moved
  // more than half the slack
  const bool rebuild_all = grid_step_ < 0 || step - grid_step_ >= interval_ || master_drift_ > 0.5 * slack_;
  if (rebuild_all) {
    BuildGrid();
    grid_step_ = step;
  }
  if (static_cast<int>(lists_.size()) <= slave_body) lists_.resize(slave_body + 1);
  auto& lists = lists_[slave_body];
  if (!keys.empty() && static_cast<int>(lists.size()) <= keys.back()) lists.resize(keys.back() + 1);
  // a node's list is rebuilt when stale or when the node left half the slack around where it was built
  std::vector<long long> built(ChunkCount(keys.size()), 0);
  ForEachChunk(keys.size(), [&](std::size_t chunk, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      NaborList& list = lists[keys[i]];
      const Vec3 p = position(keys[i]);
      if (list.built_step < grid_step_ || MaxAbs(p - list.built_at) > 0.5 * slack_) {
        BuildList(p, &list);
        list.built_step = step;
        list.built_at = p;
        ++built[chunk];
      }
    }
  });
  for (long long n : built) lists_built_ += n;
  prepared_body_ = slave_body;
}

void NeighborBoxLocator::TrianglesAlongSegment(int key, const Vec3& origin, const Vec3& dir, double length,
                                               std::vector<Candidate>* out) const {
  // the node's NaborSurf list, each surface tested exactly (segment-plane crossing, inside test)
  const double slack = kSegmentSlack * (1.0 + length);
  for (int t : lists_[prepared_body_][key].surfaces) {
    double dist = 0.0;
    if (SegmentCrossesTriangle(origin, dir, length, vertices_[triangles_[t][0]], vertices_[triangles_[t][1]],
                               vertices_[triangles_[t][2]], slack, &dist)) {
      out->push_back({t, true});
    }
  }
}

void NeighborBoxLocator::TrianglesNearPoint(int key, const Vec3& p, double radius, std::vector<Candidate>* out) const {
  // the list filtered by the current triangle bounds
  for (int t : lists_[prepared_body_][key].surfaces) {
    const Vec3& a = vertices_[triangles_[t][0]];
    const Vec3& b = vertices_[triangles_[t][1]];
    const Vec3& c = vertices_[triangles_[t][2]];
    const Vec3 nearest = p.cwiseMax(a.cwiseMin(b).cwiseMin(c)).cwiseMin(a.cwiseMax(b).cwiseMax(c));
    if ((nearest - p).norm() <= radius) out->push_back({t, false});
  }
}

LocatorFactory MakeNeighborBoxLocatorFactory(const ContactOptions& options) {
  return [options](const TriMesh& mesh) { return std::make_unique<NeighborBoxLocator>(mesh, options); };
}

}  // namespace dymesh::accel
