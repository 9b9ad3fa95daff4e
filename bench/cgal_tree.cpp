// The CGAL peer of the locate benchmarks (built only with DYMESH_WITH_CGAL).
#include "cgal_tree.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

namespace dymesh::bench {

// CGAL kernel and tree types
using Kernel = CGAL::Simple_cartesian<double>;
using Triangle = Kernel::Triangle_3;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, std::vector<Triangle>::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

struct CgalTree::Impl {
  std::vector<Triangle> triangles;
  Tree tree;
};

CgalTree::CgalTree(const TriMesh& mesh) : impl_(std::make_unique<Impl>()) {
  // the tree is built (and its distance structures accelerated) before any query is timed
  auto point = [&](int v) { return Kernel::Point_3(mesh.vertices[v].x(), mesh.vertices[v].y(), mesh.vertices[v].z()); };
  for (const auto& t : mesh.triangles) impl_->triangles.emplace_back(point(t[0]), point(t[1]), point(t[2]));
  impl_->tree.insert(impl_->triangles.cbegin(), impl_->triangles.cend());
  impl_->tree.build();
}

CgalTree::~CgalTree() = default;

size_t CgalTree::Locate(const RaySet& rays) const {
  size_t located = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    // first intersection of the ray, kept when it lies within the segment
    const Kernel::Point_3 o(rays.origin[i].x(), rays.origin[i].y(), rays.origin[i].z());
    const Kernel::Vector_3 d(rays.dir[i].x(), rays.dir[i].y(), rays.dir[i].z());
    const auto hit = impl_->tree.first_intersection(Kernel::Ray_3(o, d));
    if (!hit) continue;
    if (const Kernel::Point_3* p = boost::get<Kernel::Point_3>(&hit->first)) {
      located += CGAL::to_double((*p - o).squared_length()) <= rays.length * rays.length;
    }
  }
  return located;
}

}  // namespace dymesh::bench
