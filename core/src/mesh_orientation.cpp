// Winding every face outward: display meshes come with faces wound against their neighbours (the
// p406's door handles, the stock car's front end, a third of a forklift's body), and a face wound inward
// turns its normal into the body, which the contact reads as the outside (spec §2: the master
// surface's outward normal).
#include <algorithm>
#include <array>
#include <tuple>
#include <utility>

#include "dymesh/core/mesh.h"

namespace dymesh {
namespace {

// one use of an edge by a face: its corners as (lower, higher) index, and whether the face runs it upward
struct EdgeUse {
  int lo, hi, tri;
  bool upward;
  bool operator<(const EdgeUse& o) const { return std::tie(lo, hi, tri) < std::tie(o.lo, o.hi, o.tri); }
};

// each face's neighbours across its edges two faces share (up to three, -1 for none), whether the pair
// runs that edge the same way (then one of them is wound against the other), and whether the face has
// an edge not shared by exactly two (it lies on an open patch)
struct FaceNeighbours {
  std::vector<std::array<int, 3>> across;
  std::vector<std::array<char, 3>> same;
  std::vector<char> open;
};

FaceNeighbours NeighboursOf(const TriMesh& mesh) {
  const int n = static_cast<int>(mesh.triangles.size());
  std::vector<EdgeUse> uses;
  uses.reserve(3 * static_cast<std::size_t>(n));
  for (int t = 0; t < n; ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
      uses.push_back({std::min(a, b), std::max(a, b), t, a < b});
    }
  std::sort(uses.begin(), uses.end());
  FaceNeighbours f{std::vector<std::array<int, 3>>(n, {-1, -1, -1}), std::vector<std::array<char, 3>>(n, {0, 0, 0}),
                   std::vector<char>(n, 0)};
  auto link = [&](int t, int u, bool same) {
    int k = 0;
    while (f.across[t][k] >= 0) ++k;  // a face has three edges: at most three neighbours
    f.across[t][k] = u;
    f.same[t][k] = same ? 1 : 0;
  };
  for (std::size_t i = 0, j; i < uses.size(); i = j) {
    for (j = i + 1; j < uses.size() && uses[j].lo == uses[i].lo && uses[j].hi == uses[i].hi;) ++j;
    // an open edge, or one three faces or more share: no winding across it
    if (j - i != 2) {
      for (std::size_t k = i; k < j; ++k) f.open[uses[k].tri] = 1;
      continue;
    }
    const bool same = uses[i].upward == uses[i + 1].upward;
    link(uses[i].tri, uses[i + 1].tri, same);
    link(uses[i + 1].tri, uses[i].tri, same);
  }
  return f;
}

// six times the signed volume of the faces `patch` about `centre` (a closed patch's own volume wherever
// the centre is)
double PatchSixVolume(const TriMesh& mesh, const std::vector<int>& patch, const Vec3& centre) {
  double six_volume = 0.0;
  for (int t : patch) {
    const auto& tri = mesh.triangles[t];
    six_volume += (mesh.vertices[tri[0]] - centre).dot((mesh.vertices[tri[1]] - centre).cross(mesh.vertices[tri[2]] - centre));
  }
  return six_volume;
}

// reverses the winding of `faces`, noting each turn in `turns`
void TurnFaces(const std::vector<int>& faces, TriMesh* mesh, std::vector<char>* turns) {
  for (int t : faces) {
    std::swap(mesh->triangles[t][1], mesh->triangles[t][2]);
    (*turns)[t] ^= 1;
  }
}

// the least share of a patch's faces wound the other way at which its majority says nothing: a quarter
// (a forklift's body was 1,433 of 2,959 faces)
constexpr double kNearEvenShare = 0.25;

}  // namespace

int OrientOutward(TriMesh* mesh) {
  const int n = static_cast<int>(mesh->triangles.size());
  const FaceNeighbours f = NeighboursOf(*mesh);
  // each patch (faces joined across edges two faces share), flooded from its lowest face: the faces
  // wound against the flood's winding, whether it is closed, and whether two paths round a loop disagree
  // (a patch that cannot be wound one way, as a Moebius strip: the baja bug's body has 21 such edges)
  std::vector<char> seen(n, 0), against(n, 0), turns(n, 0);
  std::vector<std::vector<int>> by_volume;  // the patches their volume decides (below)
  for (int seed = 0; seed < n; ++seed) {
    if (seen[seed]) continue;
    std::vector<int> patch{seed};
    seen[seed] = 1;
    bool orientable = true, closed = true;
    for (std::size_t i = 0; i < patch.size(); ++i) {
      const int t = patch[i];
      closed = closed && !f.open[t];
      for (int k = 0; k < 3; ++k) {
        const int u = f.across[t][k];
        if (u < 0) continue;
        const char wound = static_cast<char>(against[t] != f.same[t][k]);
        if (seen[u]) {
          orientable = orientable && against[u] == wound;
          continue;
        }
        seen[u] = 1;
        against[u] = wound;
        patch.push_back(u);
      }
    }
    if (!orientable) continue;  // no winding to restore: left as it came
    // wound alike, the way most of its faces are
    std::vector<int> minority;
    const auto count = std::count_if(patch.begin(), patch.end(), [&](int t) { return against[t] != 0; });
    const bool keep_flood = 2 * static_cast<std::size_t>(count) <= patch.size();
    for (int t : patch)
      if ((against[t] != 0) == keep_flood) minority.push_back(t);
    TurnFaces(minority, mesh, &turns);
    // a closed patch encloses its material: its own volume decides. So does an open one whose faces were
    // split near evenly, where a majority says nothing
    const bool near_even = static_cast<double>(minority.size()) >= kNearEvenShare * static_cast<double>(patch.size());
    if (closed || near_even) by_volume.push_back(std::move(patch));
  }
  // the whole mesh outward (open game shells too: the sign about the bounds centre decides)
  if (SignedVolume(*mesh) < 0.0) FlipWinding(mesh);
  // then each patch decided by volume: about the mesh's bounds centre, which for a closed patch is its own
  const PointBounds b = BoundsOf(mesh->vertices);
  const Vec3 centre = 0.5 * (b.lo + b.hi);
  for (const std::vector<int>& patch : by_volume)
    if (PatchSixVolume(*mesh, patch, centre) < 0.0) TurnFaces(patch, mesh, &turns);
  // the faces turned on their own, not with the whole mesh
  return static_cast<int>(std::count(turns.begin(), turns.end(), 1));
}

}  // namespace dymesh
