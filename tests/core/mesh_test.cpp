// Mesh storage, welding, adjacency, subdivision, the box generator, checks and mesh file I/O.
#include "dymesh/core/mesh.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "dymesh/io/mesh_import.h"

namespace dymesh {
namespace {

namespace fs = std::filesystem;

double SurfaceArea(const TriMesh& mesh) {
  double area = 0.0;
  for (const auto& t : mesh.triangles)
    area += 0.5 * TriangleCross(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]).norm();
  return area;
}

// a fresh folder for this test's files, removed afterwards
class TempFolder {
 public:
  TempFolder() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = fs::temp_directory_path() /
            ("dymesh_mesh_test_" + std::string(info->test_suite_name()) + "_" + info->name());
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempFolder() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  fs::path operator/(const std::string& name) const { return path_ / name; }

 private:
  fs::path path_;
};

void WriteText(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

TEST(MakeBox, VolumeBoundsAndCounts) {
  const TriMesh box = MakeBox(2.0, 3.0, 4.0, 2, 3, 4);
  // V = 2 (nx ny + ny nz + nz nx) + 2, T = 4 (nx ny + ny nz + nz nx)
  const MeshStats s = ComputeStats(box);
  EXPECT_EQ(s.vertices, 54);
  EXPECT_EQ(s.triangles, 104);
  EXPECT_NEAR(SignedVolume(box), 24.0, 1e-12);
  EXPECT_NEAR(SurfaceArea(box), 2 * (6.0 + 12.0 + 8.0), 1e-12);
  EXPECT_EQ(s.min, Vec3(-1.0, -1.5, -2.0));
  EXPECT_EQ(s.max, Vec3(1.0, 1.5, 2.0));
}

TEST(MakeBox, ClosedManifoldAndOutward) {
  const TriMesh box = MakeBox(4.572, 1.6764, 0.762, 5, 3, 2);
  const MeshStats s = ComputeStats(box);
  EXPECT_EQ(s.open_edges, 0);
  EXPECT_EQ(s.nonmanifold_edges, 0);
  EXPECT_EQ(s.degenerate_triangles, 0);
  EXPECT_NEAR(SignedVolume(box), 4.572 * 1.6764 * 0.762, 1e-12);
  // every triangle's normal points away from the centre
  for (const auto& t : box.triangles) {
    const Vec3& a = box.vertices[t[0]];
    const Vec3 n = TriangleCross(a, box.vertices[t[1]], box.vertices[t[2]]);
    EXPECT_GT(n.dot((a + box.vertices[t[1]] + box.vertices[t[2]]) / 3.0), 0.0);
  }
  // Euler characteristic of a sphere: V - E + F = 2, with E = 3F/2 on a closed mesh
  EXPECT_EQ(s.vertices - 3 * s.triangles / 2 + s.triangles, 2);
}

TEST(MakeBox, SingleSegmentAndRefusals) {
  const TriMesh box = MakeBox(1.0, 1.0, 1.0, 1, 1, 1);
  EXPECT_EQ(box.vertices.size(), 8u);
  EXPECT_EQ(box.triangles.size(), 12u);
  EXPECT_THROW(MakeBox(0.0, 1.0, 1.0, 1, 1, 1), std::invalid_argument);
  EXPECT_THROW(MakeBox(1.0, 1.0, 1.0, 0, 1, 1), std::invalid_argument);
}

TEST(Subdivide, KeepsAreaVolumeAndClosedness) {
  const TriMesh box = MakeBox(2.0, 1.0, 0.5, 2, 1, 1);
  const MeshStats before = ComputeStats(box);
  const TriMesh fine = Subdivide(box);
  const MeshStats after = ComputeStats(fine);
  EXPECT_EQ(after.triangles, 4 * before.triangles);
  // one new vertex per edge (E = 3T/2 on a closed mesh)
  EXPECT_EQ(after.vertices, before.vertices + 3 * before.triangles / 2);
  EXPECT_NEAR(SurfaceArea(fine), SurfaceArea(box), 1e-12);
  EXPECT_NEAR(SignedVolume(fine), 1.0, 1e-12);
  EXPECT_EQ(after.open_edges, 0);
  EXPECT_EQ(after.nonmanifold_edges, 0);
  // twice: still closed, 16 times the triangles
  const TriMesh finer = Subdivide(fine);
  EXPECT_EQ(ComputeStats(finer).triangles, 16 * before.triangles);
  EXPECT_EQ(ComputeStats(finer).open_edges, 0);
}

TEST(MedianEdgeLength, UnitCubeAndItsSubdivision) {
  // a unit cube as 12 triangles: 12 edges of 1 and 6 face diagonals of sqrt(2), each counted once
  const TriMesh cube = MakeBox(1.0, 1.0, 1.0, 1, 1, 1);
  EXPECT_DOUBLE_EQ(MedianEdgeLength(cube), 1.0);
  // midpoint subdivision halves every edge
  EXPECT_DOUBLE_EQ(MedianEdgeLength(Subdivide(cube)), 0.5);
  EXPECT_EQ(MedianEdgeLength(TriMesh{}), 0.0);
}

TEST(Subdivide, KeepsWinding) {
  TriMesh tri;
  tri.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  tri.triangles = {{0, 1, 2}};
  const TriMesh fine = Subdivide(tri);
  ASSERT_EQ(fine.triangles.size(), 4u);
  for (const auto& t : fine.triangles)
    EXPECT_GT(TriangleCross(fine.vertices[t[0]], fine.vertices[t[1]], fine.vertices[t[2]]).z(), 0.0);
}

TEST(Weld, MergesDuplicatesInStableOrder) {
  // two triangles of a square, each with its own copy of the shared edge
  TriMesh soup;
  soup.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
  soup.triangles = {{0, 1, 2}, {3, 4, 5}};
  const TriMesh welded = Weld(soup, 1e-9);
  ASSERT_EQ(welded.vertices.size(), 4u);
  EXPECT_EQ(welded.vertices[3], Vec3(0, 1, 0));
  ASSERT_EQ(welded.triangles.size(), 2u);
  EXPECT_EQ(welded.triangles[0], (std::array<int, 3>{0, 1, 2}));
  EXPECT_EQ(welded.triangles[1], (std::array<int, 3>{0, 2, 3}));
  EXPECT_EQ(ComputeStats(welded).open_edges, 4);
}

TEST(Weld, ToleranceDecidesAndCollapsedTrianglesGo) {
  TriMesh soup;
  soup.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1e-7, 0, 0), Vec3(1, 1e-3, 0)};
  soup.triangles = {{0, 1, 2}, {3, 1, 4}};
  // within 1e-6: vertex 3 joins vertex 0; vertex 4 stays (1e-3 away)
  const TriMesh loose = Weld(soup, 1e-6);
  EXPECT_EQ(loose.vertices.size(), 4u);
  EXPECT_EQ(loose.triangles.size(), 2u);
  // within 1e-2: vertex 4 joins vertex 1, so the second triangle collapses
  const TriMesh coarse = Weld(soup, 1e-2);
  EXPECT_EQ(coarse.vertices.size(), 3u);
  EXPECT_EQ(coarse.triangles.size(), 1u);
  // tolerance 0: only identical positions merge
  EXPECT_EQ(Weld(soup, 0.0).vertices.size(), 5u);
}

TEST(Weld, BoxMadeOfSeparateFacesWeldsClosed) {
  // the box's faces as separate pieces (every vertex duplicated per triangle) weld back
  const TriMesh box = MakeBox(1.0, 2.0, 3.0, 2, 2, 2);
  TriMesh soup;
  for (const auto& t : box.triangles) {
    const int base = static_cast<int>(soup.vertices.size());
    for (int v : t) soup.vertices.push_back(box.vertices[v]);
    soup.triangles.push_back({base, base + 1, base + 2});
  }
  const TriMesh welded = Weld(soup, 1e-9);
  EXPECT_EQ(welded.vertices.size(), box.vertices.size());
  EXPECT_EQ(ComputeStats(welded).open_edges, 0);
}

TEST(RemoveDegenerateTriangles, RepeatedIndexAndZeroArea) {
  TriMesh mesh;
  mesh.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(2, 0, 0)};
  mesh.triangles = {{0, 1, 2}, {0, 0, 1}, {0, 1, 3}, {1, 2, 0}};
  EXPECT_EQ(ComputeStats(mesh).degenerate_triangles, 2);
  EXPECT_EQ(RemoveDegenerateTriangles(&mesh), 2);
  ASSERT_EQ(mesh.triangles.size(), 2u);
  EXPECT_EQ(mesh.triangles[0], (std::array<int, 3>{0, 1, 2}));
  EXPECT_EQ(mesh.triangles[1], (std::array<int, 3>{1, 2, 0}));
  EXPECT_EQ(mesh.vertices.size(), 4u);
}

TEST(BuildVertexTriangles, CsrListsEveryUse) {
  const TriMesh box = MakeBox(1.0, 1.0, 1.0, 2, 1, 1);
  const VertexTriangles adj = BuildVertexTriangles(box);
  ASSERT_EQ(adj.offsets.size(), box.vertices.size() + 1);
  EXPECT_EQ(adj.offsets.back(), static_cast<int>(3 * box.triangles.size()));
  for (int v = 0; v < static_cast<int>(box.vertices.size()); ++v) {
    for (int k = adj.offsets[v]; k < adj.offsets[v + 1]; ++k) {
      const auto& t = box.triangles[adj.ids[k]];
      EXPECT_TRUE(t[0] == v || t[1] == v || t[2] == v);
      if (k > adj.offsets[v]) {
        EXPECT_LT(adj.ids[k - 1], adj.ids[k]);
      }
    }
  }
}

// a closed mesh's volume is the same about any point; a flat sheet, turned out of every axis plane,
// has none about its surface centroid but some about its bounds centre (off its plane)
TEST(SignedVolumeAbout, AnyPointForClosedMeshesTheCentroidForSheets) {
  const TriMesh box = MakeBox(2.0, 3.0, 4.0, 2, 3, 4);
  for (const Vec3& p : {Vec3(0, 0, 0), Vec3(10, -5, 3), SurfaceCentroid(box)})
    EXPECT_NEAR(SignedVolumeAbout(box, p), 24.0, 1e-12) << p.transpose();
  TriMesh sheet;
  sheet.vertices = {Vec3(0.535623, 0.854032, 0.972764), Vec3(0.590014, 0.765874, 0.851068),
                    Vec3(0.524485, 0.787274, 0.978955)};
  sheet.triangles = {{0, 1, 2}};
  const double size = 0.17;  // the triangle's bounds diagonal, about: round-off is near 1e-16 of size cubed
  EXPECT_LT(std::abs(SignedVolumeAbout(sheet, SurfaceCentroid(sheet))), 1e-15 * size * size * size);
  EXPECT_GT(std::abs(SignedVolume(sheet)), 1e-6 * size * size * size);  // the old test's reading
}

TEST(FlipWinding, NegatesVolume) {
  TriMesh box = MakeBox(1.0, 2.0, 3.0, 1, 1, 1);
  FlipWinding(&box);
  EXPECT_NEAR(SignedVolume(box), -6.0, 1e-12);
}

TEST(MeshFiles, WriteObjThenLoadRoundTrip) {
  const TempFolder dir;
  const TriMesh box = MakeBox(1.5, 0.5, 0.25, 3, 1, 1);
  const std::string path = (dir / "box.obj").string();
  WriteObj(box, path, "test box\nsecond line");
  EXPECT_FALSE(fs::exists(path + ".tmp"));
  const TriMesh loaded = LoadMeshFile(path, "mesh.file");
  EXPECT_EQ(loaded.vertices.size(), box.vertices.size());
  EXPECT_EQ(loaded.triangles.size(), box.triangles.size());
  EXPECT_NEAR(SignedVolume(loaded), 1.5 * 0.5 * 0.25, 1e-8);
  EXPECT_EQ(ComputeStats(loaded).open_edges, 0);
}

TEST(MeshFiles, WriteObjToMissingFolderThrows) {
  const TempFolder dir;
  EXPECT_THROW(WriteObj(MakeBox(1, 1, 1, 1, 1, 1), (dir / "no" / "such" / "x.obj").string(), ""), std::runtime_error);
}

TEST(MeshFiles, LoadRefusesMissingAndGarbage) {
  const TempFolder dir;
  const std::string missing = (dir / "missing.obj").string();
  try {
    LoadMeshFile(missing, "bodies[0].mesh.file");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), missing);
    EXPECT_EQ(e.field(), "bodies[0].mesh.file");
  }
  const std::string garbage = (dir / "garbage.obj").string();
  WriteText(garbage, "this is not a mesh\nf 7 8 9\n");
  try {
    LoadMeshFile(garbage, "bodies[0].mesh.file");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), garbage);
    EXPECT_EQ(e.field(), "bodies[0].mesh.file");
  }
}

// the message of the InputError loading `text` as `name` raises ("" when it loads)
std::string LoadProblem(const TempFolder& dir, const std::string& name, const std::string& text) {
  const std::string path = (dir / name).string();
  WriteText(path, text);
  try {
    LoadMeshFile(path, "bodies[0].mesh.file");
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.field(), "bodies[0].mesh.file");
    return e.what();
  }
  return "";
}

// assimp aborted (a face of no corners, counts the data does not hold), crashed (an index past the
// vertices) or reserved a header's billion vertices on these; each is now refused by line
TEST(MeshFiles, PlyAndOffWhoseCountsOrIndicesAreWrongAreRefused) {
  const TempFolder dir;
  const std::string ply = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                          "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                          "0 0 0\n1 0 0\n0 1 0\n";
  EXPECT_EQ(LoadProblem(dir, "ok.ply", ply + "3 0 1 2\n"), "");
  EXPECT_NE(LoadProblem(dir, "past.ply", ply + "4 0 1 2 99\n").find("vertex index \"99\" is not one of the 3"), std::string::npos);
  EXPECT_NE(LoadProblem(dir, "minus.ply", ply + "3 -1 0 1\n").find("vertex index \"-1\""), std::string::npos);
  EXPECT_NE(LoadProblem(dir, "none.ply", ply + "0\n").find("at least three vertices"), std::string::npos);
  EXPECT_NE(LoadProblem(dir, "short.ply", ply).find("the file ends after 0"), std::string::npos);
  // a face element led by another property than its index list is counted, not read as a face
  std::string flagged = ply;
  flagged.replace(flagged.find("property list"), 0, "property uchar flags\n");
  EXPECT_EQ(LoadProblem(dir, "flagged.ply", flagged + "7 3 0 1 2\n"), "");
  std::string lying = ply;
  lying.replace(lying.find("vertex 3"), 8, "vertex 1000000000");
  EXPECT_NE(LoadProblem(dir, "lying.ply", lying + "3 0 1 2\n").find("counts 1000000000 vertex lines"), std::string::npos);
  // binary: the counts must fit in the bytes after the header (3 floats per vertex, a list per face)
  const std::string binary = "ply\nformat binary_little_endian 1.0\nelement vertex 1000000000\nproperty float x\n"
                             "property float y\nproperty float z\nend_header\n";
  EXPECT_NE(LoadProblem(dir, "lying_binary.ply", binary + std::string(36, '\0')).find("need at least 12000000000 bytes"),
            std::string::npos);
  // binary faces are read through too (assimp dropped one with an index past the vertices unsaid):
  // 3 vertices, then faces as a uchar count and int indices, in both byte orders
  for (const bool big : {false, true}) {
    const std::string header = std::string("ply\nformat binary_") + (big ? "big" : "little") +
                               "_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                               "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    const std::string vertices(36, '\0');  // three vertices at the origin: only the faces are judged here
    auto face = [big](std::vector<int> corners) {
      std::string bytes(1, static_cast<char>(corners.size()));
      for (const int c : corners)
        for (int b = 0; b < 4; ++b) bytes += static_cast<char>((static_cast<unsigned>(c) >> (8 * (big ? 3 - b : b))) & 0xFF);
      return bytes;
    };
    EXPECT_EQ(LoadProblem(dir, "face.ply", header + vertices + face({0, 1, 2})).find("binary PLY face"), std::string::npos);
    EXPECT_NE(LoadProblem(dir, "past_binary.ply", header + vertices + face({0, 1, 9}))
                  .find("binary PLY face 0: vertex index 9 is not one of the 3 vertices"), std::string::npos) << big;
    EXPECT_NE(LoadProblem(dir, "minus_binary.ply", header + vertices + face({0, -1, 2})).find("vertex index -1"),
              std::string::npos) << big;
    EXPECT_NE(LoadProblem(dir, "two_binary.ply", header + vertices + face({0, 1}) + std::string(4, '\0'))
                  .find("expected a face of 3 to"), std::string::npos) << big;
  }
  const std::string off = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n";
  EXPECT_EQ(LoadProblem(dir, "ok.off", off + "3 0 1 2\n"), "");
  EXPECT_NE(LoadProblem(dir, "past.off", off + "3 0 1 7\n").find("vertex index \"7\""), std::string::npos);
  EXPECT_NE(LoadProblem(dir, "lying.off", "OFF\n3 5 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n").find("the file ends after 4"),
            std::string::npos);
  // an OBJ integer part assimp's 64-bit reader overflows (it read this as 0)
  EXPECT_NE(LoadProblem(dir, "long.obj", "v -9999999999999999999999999 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").find("expected a number, got \"-999"),
            std::string::npos);
  EXPECT_EQ(LoadProblem(dir, "fine.obj", "v -0.12345678901234567890123 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), "");
}

// an ASCII PLY record holds a value per property and no more: assimp read a short vertex line's missing
// coordinate from the next line (the cube came out 4 m tall) and ignored an index past a face's count
TEST(MeshFiles, PlyRecordsHoldTheirPropertiesValuesAndNoMore) {
  const TempFolder dir;
  const std::string header = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                             "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  EXPECT_EQ(LoadProblem(dir, "ok.ply", header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"), "");
  EXPECT_NE(LoadProblem(dir, "short.ply", header + "0 0 0\n1 0\n0 1 0\n3 0 1 2\n")
                .find("line 11 (\"1 0\"): the line ends after 2 values; its properties ask for more"), std::string::npos);
  EXPECT_NE(LoadProblem(dir, "long.ply", header + "0 0 0\n1 0 0 5\n0 1 0\n3 0 1 2\n").find("expected 3 values, got more (\"5\")"),
            std::string::npos);
  EXPECT_NE(LoadProblem(dir, "extra.ply", header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2 7\n").find("expected 4 values, got more (\"7\")"),
            std::string::npos);
  EXPECT_NE(LoadProblem(dir, "word.ply", header + "0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n").find("expected a number, got \"zero\""),
            std::string::npos);
}

// assimp picks its reader by the file's extension, or, for one it does not know, by the content: a PLY
// named .dat passed the text checks and crashed it, aborted it or dropped a face unsaid
TEST(MeshFiles, UnknownExtensionIsRefused) {
  const TempFolder dir;
  const std::string ply = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                          "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                          "0 0 0\n1 0 0\n0 1 0\n3 0 1 4000000000\n";
  EXPECT_NE(LoadProblem(dir, "cube.dat", ply).find("unknown mesh file extension \".dat\": expected one assimp reads by name"),
            std::string::npos);
  EXPECT_NE(LoadProblem(dir, "cube", ply).find("unknown mesh file extension \"\""), std::string::npos);
  EXPECT_EQ(LoadProblem(dir, "TRI.OBJ", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), "");  // any case
}

// a glTF of three vertices and two triangles in `bin` (an external buffer), the second triangle's last
// index `last`
std::string TwoTriangleGltf(const TempFolder& dir, const std::string& bin, unsigned last) {
  const float vertices[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const unsigned indices[6] = {0, 1, 2, 0, 2, last};
  std::ofstream out(dir / bin, std::ios::binary);
  out.write(reinterpret_cast<const char*>(vertices), sizeof vertices);
  out.write(reinterpret_cast<const char*>(indices), sizeof indices);
  return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
    "buffers": [{"byteLength": 60, "uri": ")" + bin + R"("}],
    "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 24}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
                  {"bufferView": 1, "componentType": 5125, "count": 6, "type": "SCALAR"}]})";
}

// assimp drops a glTF face with an index past the vertices and only warns; it opens the files a model
// references as they come (a FIFO blocked the run)
TEST(MeshFiles, DroppedFacesAndReferencedFifosAreRefused) {
  const TempFolder dir;
  EXPECT_EQ(LoadProblem(dir, "two.gltf", TwoTriangleGltf(dir, "two.bin", 1)), "");
  EXPECT_NE(LoadProblem(dir, "past.gltf", TwoTriangleGltf(dir, "past.bin", 99))
                .find("assimp left part of the mesh out: Some faces had out-of-range indices. Those faces were dropped."),
            std::string::npos);
  // read again in the same process (assimp's logger drops a message that repeats the one before)
  EXPECT_NE(LoadProblem(dir, "past.gltf", TwoTriangleGltf(dir, "past.bin", 99)).find("assimp left part of the mesh out"),
            std::string::npos);
  ASSERT_EQ(mkfifo((dir / "pipe.bin").c_str(), 0644), 0);
  const std::string gltf = TwoTriangleGltf(dir, "unused.bin", 1);
  std::string piped = gltf;
  piped.replace(piped.find("unused.bin"), 10, "pipe.bin");
  const std::string problem = LoadProblem(dir, "piped.gltf", piped);
  EXPECT_NE(problem.find("cannot read mesh file: "), std::string::npos) << problem;
  EXPECT_NE(problem.find("pipe.bin: a FIFO (named pipe), not a file)"), std::string::npos) << problem;
  // an OBJ's material library is not needed: a FIFO there is skipped, the mesh read
  ASSERT_EQ(mkfifo((dir / "pipe.mtl").c_str(), 0644), 0);
  EXPECT_EQ(LoadProblem(dir, "materials.obj", "mtllib pipe.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), "");
}

// assimp ends a line at a CR or a form feed inside it, and a number at a NUL, where the checks read on:
// it dropped "f 1 3<CR>2" as a face of two corners and aborted on a form feed in a PLY vertex line
TEST(MeshFiles, ControlCharactersInsideALineAreRefused) {
  const TempFolder dir;
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  EXPECT_EQ(LoadProblem(dir, "crlf.obj", "v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3\r\n"), "");  // CRLF endings read
  EXPECT_EQ(LoadProblem(dir, "tab.obj", tri + "f\t1 2 3\n"), "");
  EXPECT_NE(LoadProblem(dir, "cr.obj", tri + "f 1 3\r2\n").find("line 4 (\"f 1 3\\r2\"): a control character (byte 13) inside the line"),
            std::string::npos);
  const std::string ply = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                          "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  EXPECT_NE(LoadProblem(dir, "ff.ply", ply + "0 0 0\n1 0\f 0\n0 1 0\n3 0 1 2\n").find("a control character (byte 12)"),
            std::string::npos);
  EXPECT_NE(LoadProblem(dir, "nul.ply", ply + "0 0 0\n1 0 0\n0 1." + std::string(1, '\0') + "5 0\n3 0 1 2\n")
                .find("a control character (byte 0)"), std::string::npos);
  EXPECT_NE(LoadProblem(dir, "cr.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 2\r1\n").find("a control character (byte 13)"),
            std::string::npos);
  // a file of vertices only is refused by its own words (assimp's: "all meshes are orphaned")
  EXPECT_NE(LoadProblem(dir, "points.obj", tri).find("no face lines (\"f\")"), std::string::npos);
}

// assimp's message on an unreadable file is quoted shortened (its STL reader quoted the rest of the file)
TEST(MeshFiles, AssimpMessageIsQuotedShort) {
  const TempFolder dir;
  std::string stl = "solid t\nfacet normal 0 0 0\nouter loop\nvertex 0 0 x\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n";
  for (int i = 0; i < 50; ++i) stl += "facet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n";
  const std::string problem = LoadProblem(dir, "bad.stl", stl + "endsolid t\n");
  EXPECT_NE(problem.find("cannot read mesh file: "), std::string::npos) << problem;
  // 200 characters quoted, plus the file's path (a temporary folder), the field and the prefix
  EXPECT_LT(problem.size(), 400u) << problem;
}

TEST(BuildBodyMesh, MapsAxesScalesAndFits) {
  const TempFolder dir;
  const std::string path = (dir / "yup.obj").string();
  // a y-up box: 4 long (x), 1 tall (y), 2 wide (z), in mm
  WriteObj(MakeBox(4000.0, 1000.0, 2000.0, 2, 1, 1), path, "y-up box");
  MeshSource source;
  source.file = path;
  source.scale = 1e-3;
  source.axes = {"x", "z", "-y"};
  const TriMesh body = BuildBodyMesh(source, "(test)", "bodies[0].mesh");
  const MeshStats s = ComputeStats(body);
  EXPECT_NEAR(s.max.x() - s.min.x(), 4.0, 1e-9);
  EXPECT_NEAR(s.max.y() - s.min.y(), 2.0, 1e-9);
  EXPECT_NEAR(s.max.z() - s.min.z(), 1.0, 1e-9);
  EXPECT_NEAR(SignedVolume(body), 8.0, 1e-8);
  // fit the body-x extent to 5 m (uniform)
  source.fit_length = 5.0;
  const MeshStats fitted = ComputeStats(BuildBodyMesh(source, "(test)", "bodies[0].mesh"));
  EXPECT_NEAR(fitted.max.x() - fitted.min.x(), 5.0, 1e-9);
  EXPECT_NEAR(fitted.max.y() - fitted.min.y(), 2.5, 1e-9);
  // one subdivision: four times the triangles
  source.fit_length.reset();
  source.subdivisions = 1;
  EXPECT_EQ(BuildBodyMesh(source, "(test)", "bodies[0].mesh").triangles.size(), 4 * body.triangles.size());
}

TEST(BuildBodyMesh, OrientsInwardMeshOutward) {
  const TempFolder dir;
  TriMesh inward = MakeBox(1.0, 1.0, 1.0, 1, 1, 1);
  FlipWinding(&inward);
  const std::string path = (dir / "inward.obj").string();
  WriteObj(inward, path, "inward box");
  MeshSource source;
  source.file = path;
  EXPECT_NEAR(SignedVolume(BuildBodyMesh(source, "(test)", "m")), 1.0, 1e-9);
  // an improper mapping (a mirror) also ends outward
  source.axes = {"-x", "y", "z"};
  EXPECT_NEAR(SignedVolume(BuildBodyMesh(source, "(test)", "m")), 1.0, 1e-9);
}

// each face's corners in a rotation that starts at its lowest index (the same face, wound the same way)
std::vector<std::array<int, 3>> CanonicalFaces(const TriMesh& mesh) {
  std::vector<std::array<int, 3>> faces;
  for (auto t : mesh.triangles) {
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    faces.push_back(t);
  }
  return faces;
}

// the faces as their corners' places, each from its least corner on, sorted: the same surface wound the
// same way whatever the vertices' numbering
std::vector<std::array<std::array<double, 3>, 3>> FacesByPlace(const TriMesh& mesh) {
  std::vector<std::array<std::array<double, 3>, 3>> faces;
  for (const auto& t : mesh.triangles) {
    std::array<std::array<double, 3>, 3> f;
    for (int k = 0; k < 3; ++k) f[k] = {mesh.vertices[t[k]].x(), mesh.vertices[t[k]].y(), mesh.vertices[t[k]].z()};
    std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
    faces.push_back(f);
  }
  std::sort(faces.begin(), faces.end());
  return faces;
}

// every edge two faces share is run once each way: the faces agree on their winding
bool WoundAlike(const TriMesh& mesh) {
  std::set<std::pair<int, int>> runs;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      if (!runs.insert({t[k], t[(k + 1) % 3]}).second) return false;
  return true;
}

TEST(OrientOutward, TurnsFacesWoundAgainstTheirNeighboursAndInwardClosedParts) {
  // a box (2 x 1 x 1 m, 4 x 2 x 2 cells) with every third face wound inward: all outward again, the
  // same faces as the box's own, the turned ones counted
  const TriMesh box = MakeBox(2.0, 1.0, 1.0, 4, 2, 2);
  const int third = static_cast<int>((box.triangles.size() + 2) / 3);
  TriMesh mixed = box;
  for (std::size_t t = 0; t < mixed.triangles.size(); t += 3) std::swap(mixed.triangles[t][1], mixed.triangles[t][2]);
  EXPECT_FALSE(WoundAlike(mixed));
  EXPECT_EQ(OrientOutward(&mixed), third);
  EXPECT_EQ(CanonicalFaces(mixed), CanonicalFaces(box));
  // the whole box wound inward but a third of its faces: the third turned against their patch, then
  // the whole mesh
  TriMesh inward = box;
  FlipWinding(&inward);
  for (std::size_t t = 0; t < inward.triangles.size(); t += 3) std::swap(inward.triangles[t][1], inward.triangles[t][2]);
  EXPECT_EQ(OrientOutward(&inward), third);
  EXPECT_EQ(CanonicalFaces(inward), CanonicalFaces(box));
  // a closed part wound inward inside an outward body (a wheel mirrored in modelling): it encloses its
  // material, so it faces out by its own volume, 8 + 1 m^3 in all
  TriMesh two = MakeBox(4.0, 2.0, 1.0, 2, 2, 1);
  TriMesh part = MakeBox(1.0, 1.0, 1.0, 1, 1, 1);
  FlipWinding(&part);
  const int offset = static_cast<int>(two.vertices.size());
  for (const Vec3& v : part.vertices) two.vertices.push_back(v + Vec3(0.5, 0.0, 0.0));
  for (const auto& t : part.triangles) two.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  EXPECT_EQ(OrientOutward(&two), 12);
  EXPECT_NEAR(SignedVolume(two), 9.0, 1e-12);
  EXPECT_TRUE(WoundAlike(two));
  // an open shell (the box without its top) with every other face wound inward, an even split no
  // majority decides: wound out of the body by its volume about the centre, as the box's own faces
  TriMesh open_box = box;
  std::erase_if(open_box.triangles, [&](const std::array<int, 3>& t) {
    return box.vertices[t[0]].z() > 0.49 && box.vertices[t[1]].z() > 0.49 && box.vertices[t[2]].z() > 0.49;
  });
  const TriMesh open_given = open_box;
  for (std::size_t t = 0; t < open_box.triangles.size(); t += 2)
    std::swap(open_box.triangles[t][1], open_box.triangles[t][2]);
  OrientOutward(&open_box);
  EXPECT_EQ(CanonicalFaces(open_box), CanonicalFaces(open_given));
  // an open sheet of two faces wound against each other keeps its first face's winding on the tie
  TriMesh sheet;
  sheet.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
  sheet.triangles = {{0, 1, 2}, {0, 3, 2}};
  EXPECT_EQ(OrientOutward(&sheet), 1);
  EXPECT_TRUE(WoundAlike(sheet));
  // a Moebius strip of six faces cannot be wound one way: left as it came
  TriMesh strip;
  for (int k = 0; k < 3; ++k) {
    const double a = 2.0 * 3.14159265358979 * k / 6.0, half = 0.5 * a;
    for (double w : {-0.2, 0.2})
      strip.vertices.emplace_back((1.0 + w * std::cos(half)) * std::cos(a), (1.0 + w * std::cos(half)) * std::sin(a), w * std::sin(half));
  }
  // three quads round the loop, the last joining the far end to the start turned over (0 <-> 1)
  strip.triangles = {{0, 2, 3}, {0, 3, 1}, {2, 4, 5}, {2, 5, 3}, {4, 1, 0}, {4, 0, 5}};
  TriMesh strip_given = strip;
  EXPECT_EQ(OrientOutward(&strip), 0);
  if (SignedVolume(strip_given) < 0.0) FlipWinding(&strip_given);  // the whole-mesh rule still applies
  EXPECT_EQ(CanonicalFaces(strip), CanonicalFaces(strip_given));
  // a consistent outward mesh is left exactly as it was
  TriMesh same = box;
  EXPECT_EQ(OrientOutward(&same), 0);
  EXPECT_EQ(same.triangles, box.triangles);
}

TEST(BuildBodyMesh, FacesWoundAgainstTheirNeighboursAreTurned) {
  // the same box written with a third of its faces wound inward builds the same body as the clean file
  const TempFolder dir;
  const TriMesh box = MakeBox(4.572, 1.6764, 0.762, 1, 22, 10);
  TriMesh mixed = box;
  for (std::size_t t = 0; t < mixed.triangles.size(); t += 3) std::swap(mixed.triangles[t][1], mixed.triangles[t][2]);
  WriteObj(box, (dir / "clean.obj").string(), "clean box");
  WriteObj(mixed, (dir / "mixed.obj").string(), "a third of the faces wound inward");
  MeshSource clean, turned;
  clean.file = (dir / "clean.obj").string();
  turned.file = (dir / "mixed.obj").string();
  // (the vertices are numbered as the faces first meet them: the faces compared by their corners' places)
  EXPECT_EQ(FacesByPlace(BuildBodyMesh(clean, "(test)", "m")), FacesByPlace(BuildBodyMesh(turned, "(test)", "m")));
}

TEST(BuildBodyMesh, BoxAndRefusedAxes) {
  MeshSource box;
  box.box = true;
  box.box_size = Vec3(4.0, 2.0, 1.0);
  box.box_segments = {4, 2, 1};
  EXPECT_NEAR(SignedVolume(BuildBodyMesh(box, "(test)", "m")), 8.0, 1e-12);
  MeshSource bad;
  bad.file = "/nonexistent.obj";
  bad.axes = {"x", "x", "z"};
  try {
    BuildBodyMesh(bad, "scenario.json", "bodies[1].mesh");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "scenario.json");
    EXPECT_EQ(e.field(), "bodies[1].mesh.axes");
  }
}

TEST(ReferenceMeshes, LoadAndOrient) {
  // the repository's vehicle meshes load, with the documented body-axes mapping
  for (const char* name : {"torcs_p406.obj", "torcs_p406-lod3.obj", "torcs_car1-stock1.obj", "cesium_milk_truck.obj"}) {
    MeshSource source;
    source.file = std::string(DYMESH_DATA_DIR) + "/meshes/" + name;
    source.axes = {"x", "z", "-y"};
    const TriMesh body = BuildBodyMesh(source, "(test)", "m");
    const MeshStats s = ComputeStats(body);
    EXPECT_GT(s.triangles, 1000) << name;
    EXPECT_GT(SignedVolume(body), 0.0) << name;
    // SAE body axes: longer than wide, roof at negative z, ground near z = 0
    EXPECT_GT(s.max.x() - s.min.x(), s.max.y() - s.min.y()) << name;
    EXPECT_LT(s.min.z(), -1.0) << name;
    EXPECT_NEAR(s.max.z(), 0.0, 0.01) << name;
  }
}

}  // namespace
}  // namespace dymesh
