#include "assimp_read.h"

#include <assimp/DefaultIOSystem.h>
#include <assimp/DefaultLogger.hpp>
#include <assimp/Importer.hpp>
#include <assimp/LogStream.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <mutex>
#include <vector>

#include "dymesh/io/printable.h"
#include "dymesh/io/scenario_json.h"

namespace dymesh {
namespace {

// the most of one assimp message a refusal quotes
constexpr std::size_t kMaxQuoted = 200;

// assimp's file system, regular files only: a file a model references that is a FIFO would block the
// read; the first one refused is kept for the message
class RegularFilesOnly : public Assimp::DefaultIOSystem {
 public:
  bool Exists(const char* file) const override { return NotARegularFile(file).empty(); }
  Assimp::IOStream* Open(const char* file, const char* mode) override {
    const std::string problem = NotARegularFile(file);
    if (problem.empty()) return DefaultIOSystem::Open(file, mode);
    if (refused_.empty()) refused_ = std::string(file) + ": " + problem;
    return nullptr;
  }
  const std::string& refused() const { return refused_; }

 private:
  std::string refused_;
};

// assimp's warnings and errors, collected by the thread that reads (its logger is process-wide)
thread_local std::vector<std::string>* warnings_sink = nullptr;

class WarningSink : public Assimp::LogStream {
 public:
  void write(const char* message) override {
    // "Warn,  T0: text": the text
    std::string text = message;
    if (const auto colon = text.find(": "); colon != std::string::npos && colon < 16) text.erase(0, colon + 2);
    if (warnings_sink != nullptr) warnings_sink->push_back(text);
  }
};

// the process-wide logger, created once, writing warnings and errors to the reading thread's sink only
void AttachWarningSink() {
  static std::once_flag once;
  std::call_once(once, [] {
    Assimp::DefaultLogger::create("", Assimp::Logger::NORMAL, 0);
    Assimp::DefaultLogger::get()->attachStream(new WarningSink, Assimp::Logger::Warn | Assimp::Logger::Err);
  });
}

// a message quoted in a refusal: printable, one line, at most kMaxQuoted characters
std::string Quoted(std::string text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
  if (text.size() > kMaxQuoted) text = text.substr(0, kMaxQuoted) + "...";
  return Printable(text);
}

// whether `text` holds any of `words`
bool Mentions(const std::string& text, std::initializer_list<const char*> words) {
  return std::any_of(words.begin(), words.end(), [&](const char* w) { return text.find(w) != std::string::npos; });
}

// a warning that assimp left geometry out: faces or vertices dropped, skipped or with an index out of
// range (not materials, texture coordinates, colours, bones or animation, which the model does not read)
bool DropsGeometry(const std::string& warning) {
  std::string w = warning;
  std::transform(w.begin(), w.end(), w.begin(), [](unsigned char c) { return std::tolower(c); });
  return Mentions(w, {"face", "index", "indices", "vertex", "vertices", "polygon", "triangle"}) &&
         Mentions(w, {"out of range", "out-of-range", "invalid", "dropped", "ignor", "skipp", "malformed"}) &&
         !Mentions(w, {"material", "textur", "uv", "colo", "bone", "channel", "normal", "anim", "weight", "frame",
                       "surface", "clip", "light", "camera", "token", "type", "name", "comment", "ptag", "degenerate"});
}

}  // namespace

TriMesh ReadMeshWithAssimp(const std::string& path, const std::string& field) {
  Assimp::Importer importer;
  // a known extension: assimp picks the reader by name, as the text checks do
  const std::string extension = std::filesystem::path(path).extension().string();
  if (!importer.IsExtensionSupported(extension))
    throw InputError(path, field,
                     "unknown mesh file extension \"" + Printable(extension) +
                         "\": expected one assimp reads by name (.obj, .stl, .ply, .off, .gltf, .glb, .fbx, .dae, ...)");
  auto* files = new RegularFilesOnly;  // the importer owns it
  importer.SetIOHandler(files);
  AttachWarningSink();
  std::vector<std::string> warnings;
  warnings_sink = &warnings;
  const aiScene* scene = importer.ReadFile(
      path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_PreTransformVertices);
  warnings_sink = nullptr;
  if (scene == nullptr) {
    const std::string why = files->refused().empty() ? "" : " (" + Printable(files->refused()) + ")";
    throw InputError(path, field, "cannot read mesh file: " + Quoted(importer.GetErrorString()) + why);
  }
  for (const std::string& w : warnings)
    if (DropsGeometry(w)) throw InputError(path, field, "assimp left part of the mesh out: " + Quoted(w));
  // collect the triangles of every mesh (points and lines are skipped)
  TriMesh mesh;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* am = scene->mMeshes[m];
    const int base = static_cast<int>(mesh.vertices.size());
    for (unsigned v = 0; v < am->mNumVertices; ++v)
      mesh.vertices.emplace_back(am->mVertices[v].x, am->mVertices[v].y, am->mVertices[v].z);
    for (unsigned f = 0; f < am->mNumFaces; ++f) {
      const aiFace& face = am->mFaces[f];
      if (face.mNumIndices != 3) continue;
      // an index past the mesh's vertices (an importer that does not check them) is refused, not followed
      for (unsigned k = 0; k < 3; ++k)
        if (face.mIndices[k] >= am->mNumVertices)
          throw InputError(path, field, "a face's vertex index " + std::to_string(face.mIndices[k]) + " is past the " +
                                            std::to_string(am->mNumVertices) + " vertices assimp read");
      mesh.triangles.push_back({base + static_cast<int>(face.mIndices[0]), base + static_cast<int>(face.mIndices[1]),
                                base + static_cast<int>(face.mIndices[2])});
    }
  }
  return mesh;
}

}  // namespace dymesh
