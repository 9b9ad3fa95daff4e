#include "mesh_text_check.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "dymesh/io/printable.h"
#include "dymesh/io/scenario_json.h"

namespace dymesh {
namespace {

// most digits of an OBJ number's integer part (assimp reads it into 64 bits, which overflow past 19)
constexpr long kMaxObjDigits = 18;

// most corners of one OBJ face
constexpr std::size_t kMaxObjFaceCorners = 1000;

// most entries a PLY or OFF count may give: elements, and the corners of one face
constexpr std::uint64_t kMaxCount = UINT64_C(1) << 40, kMaxFaceListCount = UINT64_C(1) << 20;

// one property of a PLY element: a scalar, or a list (its count's type and its items' type)
struct PlyProperty {
  bool list = false;
  std::string count_type, type;
};

// one element of a PLY header: its name, count, properties, and the smallest bytes a binary record takes
struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::uint64_t min_bytes = 0;
  std::vector<PlyProperty> properties;
};

// bytes of a PLY scalar type (0 when unknown)
std::uint64_t PlyTypeBytes(const std::string& type) {
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if (type == "int" || type == "uint" || type == "float" || type == "int32" || type == "uint32" || type == "float32")
    return 4;
  if (type == "double" || type == "float64") return 8;
  return 0;
}

std::string Lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// a whole non-negative integer token below `limit`
bool IndexBelow(const std::string& token, std::uint64_t limit) {
  if (token.empty() || token.size() > 19) return false;
  for (char c : token)
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  return std::stoull(token) < limit;
}

// "line N ("...")" for messages
std::string At(long number, const std::string& line) {
  return "line " + std::to_string(number) + " (\"" + Printable(line.substr(0, 60)) + "\")";
}

// a control character inside a line (not a tab, nor the CR of a CRLF ending): assimp ends a line at a
// CR or a form feed and a number at a NUL, where the checks here read on (a face "f 1 3<CR>2" passed
// them and assimp dropped it as "f 1 3"; a form feed in a PLY vertex line aborted it)
void RefuseControlCharacters(const std::string& path, const std::string& field, long number, const std::string& line) {
  const std::size_t end = !line.empty() && line.back() == '\r' ? line.size() - 1 : line.size();
  for (std::size_t i = 0; i < end; ++i) {
    const auto c = static_cast<unsigned char>(line[i]);
    if ((c < 0x20 && c != '\t') || c == 0x7F)
      throw InputError(path, field, At(number, line) + ": a control character (byte " + std::to_string(c) +
                                        ") inside the line; expected text (assimp breaks lines and numbers there)");
  }
}

// the next data line that is not blank (and, for OFF, not a comment); false at the end of the file;
// a control character inside a line is refused
bool NextDataLine(std::istream& in, bool skip_comments, long* number, std::string* line, const std::string& path,
                  const std::string& field) {
  while (std::getline(in, *line)) {
    ++*number;
    RefuseControlCharacters(path, field, *number, *line);
    const auto first = line->find_first_not_of(" \t\r");
    if (first == std::string::npos || (skip_comments && (*line)[first] == '#')) continue;
    return true;
  }
  return false;
}

// a PLY or OFF file ends with the data its header counts: a further line (an extra face) was ignored
// without a word
void RefuseDataPastCounts(std::istream& in, bool skip_comments, long number, const std::string& path,
                          const std::string& field) {
  std::string line;
  if (NextDataLine(in, skip_comments, &number, &line, path, field))
    throw InputError(path, field, At(number, line) + ": data past the header's counts; expected the end of the file "
                                                     "(or counts that include it)");
}

// a whole number token (strtod reads all of it)
bool IsNumber(const std::string& token) {
  char* end = nullptr;
  std::strtod(token.c_str(), &end);
  return !token.empty() && end == token.c_str() + token.size();
}

// an OBJ number token read whole ("0,1" or "1abc" are not numbers; assimp reads their prefix), with at
// most kMaxObjDigits digits before its point (assimp's reader overflowed a 25-digit integer to 0)
bool IsObjNumber(const std::string& token) {
  const std::string mantissa = token.substr(0, token.find_first_of(".eE"));
  const auto digits = std::count_if(mantissa.begin(), mantissa.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
  return IsNumber(token) && token.find_first_of("xX") == std::string::npos && digits <= kMaxObjDigits;
}

// a "v" line's numbers: x y z, x y z w (w = 1) or x y z r g b, each read whole ("" when sound). assimp 5.2
// drops a vertex with a number written from a bare point (".5"; "-.5" and "0.5" read), shifting every
// later index, misreads 5 or 7 numbers the same way, and divides x, y and z by w
std::string ObjVertexProblem(const std::vector<std::string>& numbers) {
  const std::size_t n = numbers.size();
  if (n != 3 && n != 4 && n != 6)
    return "expected a vertex \"v x y z\", \"v x y z w\" or \"v x y z r g b\", got " + std::to_string(n) + " numbers";
  for (const std::string& t : numbers) {
    if (!IsObjNumber(t)) return "expected a number, got \"" + t + "\"";
    if (t.front() == '.') return "expected a digit before the point (0" + t + "), got \"" + t + "\"";
  }
  if (n == 4 && std::strtod(numbers[3].c_str(), nullptr) != 1.0)
    return "expected w = 1 (assimp divides x, y and z by w), got \"" + numbers[3] + "\"";
  return "";
}

// an OBJ face corner: v, v/vt, v//vn or v/vt/vn, each a (possibly negative) nonzero integer
bool IsObjCorner(const std::string& token) {
  std::istringstream parts(token);
  std::string part;
  int index = 0;
  while (std::getline(parts, part, '/')) {
    const bool may_be_empty = index == 1 && token.find("//") != std::string::npos;
    char* end = nullptr;
    const long value = part.empty() ? 0 : std::strtol(part.c_str(), &end, 10);
    if (!(part.empty() && may_be_empty) && (part.empty() || end != part.c_str() + part.size() || value == 0)) return false;
    ++index;
  }
  return index >= 1 && index <= 3 && token.back() != '/';
}

// assimp reads a vertex coordinate up to its first bad character and drops a face of fewer than
// three corners without a word: an OBJ file is read through once first, so that such a line is
// refused with its number
void CheckObjLines(const std::string& path, const std::string& field) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  long faces = 0;
  for (long number = 1; std::getline(in, line); ++number) {
    RefuseControlCharacters(path, field, number, line);
    std::istringstream tokens(line);
    std::string keyword, token;
    tokens >> keyword;
    std::vector<std::string> rest;
    while (tokens >> token) rest.push_back(token);
    const std::string at = At(number, line);
    if (keyword == "v") {
      if (const std::string problem = ObjVertexProblem(rest); !problem.empty()) throw InputError(path, field, at + ": " + problem);
    } else if (keyword == "f") {
      ++faces;
      if (rest.size() < 3) throw InputError(path, field, at + ": expected a face of at least three vertices");
      // assimp's triangulation of one polygon is quadratic in its corners (100,000 took 38 s)
      if (rest.size() > kMaxObjFaceCorners)
        throw InputError(path, field, at + ": a face of " + std::to_string(rest.size()) + " vertices; expected at most " +
                                          std::to_string(kMaxObjFaceCorners) + " (triangulate it first)");
      for (const std::string& t : rest)
        if (!IsObjCorner(t)) throw InputError(path, field, at + ": expected a vertex index (v, v/vt, v//vn or v/vt/vn), got \"" + t + "\"");
    }
  }
  // assimp says "all meshes are orphaned" of a file of vertices only
  if (faces == 0) throw InputError(path, field, "no face lines (\"f\"); expected a mesh of triangles or polygons");
}

// one face line: "n i1 .. in" with n >= 3 and every index below the vertex count
std::string FaceProblem(const std::string& line, std::uint64_t vertices) {
  std::istringstream tokens(line);
  std::string token;
  tokens >> token;
  if (!IndexBelow(token, kMaxFaceListCount) || std::stoull(token) < 3) return "expected a face of at least three vertices";
  const std::uint64_t corners = std::stoull(token);
  for (std::uint64_t i = 0; i < corners; ++i) {
    if (!(tokens >> token)) return "expected " + std::to_string(corners) + " vertex indices";
    if (!IndexBelow(token, vertices))
      return "vertex index \"" + token + "\" is not one of the " + std::to_string(vertices) + " vertices";
  }
  return "";
}

// one ASCII PLY record: a value per scalar property, a count and that many values per list, nothing
// more (assimp read a short vertex line's missing coordinate from the next line, and ignored a face's
// index past its count); a face's leading list names 3 or more existing vertices ("" when sound)
std::string AsciiRecordProblem(const std::string& line, const PlyElement& element, std::uint64_t vertices) {
  std::istringstream tokens(line);
  std::string token;
  std::uint64_t read = 0;
  const auto ends_early = [&] { return "the line ends after " + std::to_string(read) + " values; its properties ask for more"; };
  for (std::size_t k = 0; k < element.properties.size(); ++k) {
    const PlyProperty& p = element.properties[k];
    // a face's leading list: its vertex indices
    const bool indices = element.name == "face" && k == 0 && p.list;
    std::uint64_t values = 1;
    if (p.list) {
      if (!(tokens >> token)) return ends_early();
      ++read;
      if (!IndexBelow(token, kMaxFaceListCount)) return "expected a list count, got \"" + token + "\"";
      values = std::stoull(token);
      if (indices && values < 3) return "expected a face of at least three vertices";
    }
    for (std::uint64_t i = 0; i < values; ++i, ++read) {
      if (!(tokens >> token)) return ends_early();
      if (indices && !IndexBelow(token, vertices))
        return "vertex index \"" + token + "\" is not one of the " + std::to_string(vertices) + " vertices";
      if (!indices && !IsNumber(token)) return "expected a number, got \"" + token + "\"";
    }
  }
  if (tokens >> token) return "expected " + std::to_string(read) + " values, got more (\"" + token + "\")";
  return "";
}

// reads binary PLY records: integers of a PLY type in the file's byte order
class BinaryPlyReader {
 public:
  BinaryPlyReader(std::istream& in, bool big_endian) : in_(in), big_endian_(big_endian) {}
  // the next value of `type` as an integer (false at the end of the file or for an unknown type)
  bool Integer(const std::string& type, std::int64_t* value) {
    const std::uint64_t bytes = PlyTypeBytes(type);
    unsigned char raw[8];
    if (bytes == 0 || !in_.read(reinterpret_cast<char*>(raw), static_cast<std::streamsize>(bytes))) return false;
    std::uint64_t bits = 0;
    for (std::uint64_t i = 0; i < bytes; ++i) bits |= std::uint64_t{raw[big_endian_ ? bytes - 1 - i : i]} << (8 * i);
    // signed types are sign-extended; a float index is read as its bits (never a valid index then)
    const bool is_signed = type == "char" || type == "int8" || type == "short" || type == "int16" || type == "int" ||
                           type == "int32";
    if (is_signed && bytes < 8 && (bits >> (8 * bytes - 1)) != 0) bits |= ~std::uint64_t{0} << (8 * bytes);
    *value = static_cast<std::int64_t>(bits);
    return true;
  }
  // skips `count` values of `type` (false when the file ends first)
  bool Skip(const std::string& type, std::uint64_t count) {
    const auto bytes = static_cast<std::streamsize>(PlyTypeBytes(type) * count);
    return in_.ignore(bytes).gcount() == bytes;
  }

 private:
  std::istream& in_;
  bool big_endian_;
};

// one face's index list, its count read: 3 or more corners, each an existing vertex ("" when sound)
std::string FaceIndicesProblem(BinaryPlyReader& reader, const std::string& type, std::int64_t count,
                               std::uint64_t vertices) {
  if (count < 3 || static_cast<std::uint64_t>(count) > kMaxFaceListCount)
    return "expected a face of 3 to " + std::to_string(kMaxFaceListCount) + " vertices, got " + std::to_string(count);
  for (std::int64_t c = 0; c < count; ++c) {
    std::int64_t index = 0;
    if (!reader.Integer(type, &index)) return "the file ends inside its vertex indices";
    if (index < 0 || static_cast<std::uint64_t>(index) >= vertices)
      return "vertex index " + std::to_string(index) + " is not one of the " + std::to_string(vertices) + " vertices";
  }
  return "";
}

// every binary record read through: faces (led by their index list) checked, the rest skipped
// (assimp dropped a face with an index past the vertices without a word)
void CheckBinaryPlyFaces(std::istream& in, bool big_endian, const std::vector<PlyElement>& elements,
                         std::uint64_t vertices, const std::string& path, const std::string& field) {
  BinaryPlyReader reader(in, big_endian);
  for (const PlyElement& e : elements)
    for (std::uint64_t record = 0; record < e.count; ++record)
      for (std::size_t k = 0; k < e.properties.size(); ++k) {
        const PlyProperty& p = e.properties[k];
        std::int64_t count = 1;
        bool read = !p.list || reader.Integer(p.count_type, &count);
        if (read && e.name == "face" && k == 0 && p.list) {
          if (const std::string problem = FaceIndicesProblem(reader, p.type, count, vertices); !problem.empty())
            throw InputError(path, field, "binary PLY face " + std::to_string(record) + ": " + problem);
          continue;
        }
        read = read && count >= 0 && reader.Skip(p.type, static_cast<std::uint64_t>(count));
        if (!read) throw InputError(path, field, "binary PLY: the file ends inside its " + e.name + " data");
      }
}

void CheckPly(const std::string& path, const std::string& field) {
  std::ifstream in(path, std::ios::binary);
  std::string line, format;
  std::vector<PlyElement> elements;
  long number = 0;
  // header: the elements in order, their counts and record sizes
  while (std::getline(in, line)) {
    ++number;
    RefuseControlCharacters(path, field, number, line);
    std::istringstream tokens(line);
    std::string keyword;
    tokens >> keyword;
    if (keyword == "end_header") break;
    if (keyword == "format") tokens >> format;
    if (keyword == "element") {
      PlyElement e;
      std::string count;
      tokens >> e.name >> count;
      if (!IndexBelow(count, kMaxCount)) throw InputError(path, field, At(number, line) + ": expected an element count");
      e.count = std::stoull(count);
      elements.push_back(e);
    }
    if (keyword == "property" && !elements.empty()) {
      std::string type;
      tokens >> type;
      PlyProperty property;
      property.list = type == "list";
      if (property.list) tokens >> property.count_type >> type;
      property.type = type;
      elements.back().properties.push_back(property);
      // a list takes at least its count
      elements.back().min_bytes += PlyTypeBytes(property.list ? property.count_type : type);
    }
  }
  if (line.rfind("end_header", 0) != 0) throw InputError(path, field, "PLY header has no end_header");
  std::uint64_t vertices = 0;
  for (const PlyElement& e : elements)
    if (e.name == "vertex") vertices = e.count;
  // binary: the counts must fit in the bytes after the header
  if (format != "ascii") {
    const std::uint64_t left = std::filesystem::file_size(path) - static_cast<std::uint64_t>(in.tellg());
    std::uint64_t need = 0;
    for (const PlyElement& e : elements) need += e.count * std::max<std::uint64_t>(e.min_bytes, 1);
    if (need > left)
      throw InputError(path, field, "PLY header counts need at least " + std::to_string(need) + " bytes of data; the file has " +
                                        std::to_string(left));
    CheckBinaryPlyFaces(in, format == "binary_big_endian", elements, vertices, path, field);
    return;
  }
  // ASCII: every counted line is there and holds its properties' values, faces (led by their index
  // list) name existing vertices
  for (const PlyElement& e : elements)
    for (std::uint64_t i = 0; i < e.count; ++i) {
      const auto too_few = [&](std::uint64_t lines) {
        return InputError(path, field, "PLY header counts " + std::to_string(e.count) + " " + e.name +
                                           " lines; the file ends after " + std::to_string(lines));
      };
      if (!NextDataLine(in, false, &number, &line, path, field)) throw too_few(i);
      const std::string problem = AsciiRecordProblem(line, e, vertices);
      if (problem.empty()) continue;
      // a line that does not fit is most often the data ending before the counts: say that, if so
      const long at = number;
      std::uint64_t after = 0;
      for (std::string rest; after + i + 1 < e.count && NextDataLine(in, false, &number, &rest, path, field);) ++after;
      if (after + i + 1 < e.count) throw too_few(i + 1 + after);
      throw InputError(path, field, At(at, line) + ": " + problem);
    }
  RefuseDataPastCounts(in, false, number, path, field);
}

void CheckOff(const std::string& path, const std::string& field) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  long number = 0;
  // "OFF" (maybe with the counts on the same line), then "vertices faces edges"
  if (!NextDataLine(in, true, &number, &line, path, field)) throw InputError(path, field, "empty OFF file");
  std::istringstream head(line);
  std::string keyword, v, f;
  head >> keyword;
  if (keyword.find("OFF") == std::string::npos) throw InputError(path, field, At(number, line) + ": expected \"OFF\"");
  if (!(head >> v >> f)) {
    if (!NextDataLine(in, true, &number, &line, path, field)) throw InputError(path, field, "OFF file has no counts line");
    std::istringstream counts(line);
    counts >> v >> f;
  }
  if (!IndexBelow(v, kMaxCount) || !IndexBelow(f, kMaxCount))
    throw InputError(path, field, At(number, line) + ": expected the vertex and face counts");
  const std::uint64_t vertices = std::stoull(v), faces = std::stoull(f);
  for (std::uint64_t i = 0; i < vertices + faces; ++i) {
    if (!NextDataLine(in, true, &number, &line, path, field))
      throw InputError(path, field, "OFF header counts " + v + " vertices and " + f + " faces; the file ends after " +
                                        std::to_string(i) + " lines of them");
    if (i < vertices) continue;
    if (const std::string problem = FaceProblem(line, vertices); !problem.empty())
      throw InputError(path, field, At(number, line) + ": " + problem);
  }
  RefuseDataPastCounts(in, true, number, path, field);
}

// a binary STL: 84 bytes of header and count, then 50 bytes per triangle (the count must fill the
// file exactly; an ASCII file may begin "solid" too)
bool IsBinaryStl(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char head[84] = {};
  if (!in.read(head, sizeof head)) return false;
  std::uint32_t count = 0;
  for (int i = 0; i < 4; ++i) count |= std::uint32_t{static_cast<unsigned char>(head[80 + i])} << (8 * i);
  return std::filesystem::file_size(path) == 84 + 50 * std::uint64_t{count} || std::string(head, 5) != "solid";
}

// an ASCII STL's facets hold three vertices each between "outer loop" and "endloop" (assimp dropped a
// fourth vertex without a word)
void CheckAsciiStl(const std::string& path, const std::string& field) {
  if (IsBinaryStl(path)) return;
  std::ifstream in(path, std::ios::binary);
  std::string line;
  int corners = 0;
  for (long number = 1; std::getline(in, line); ++number) {
    RefuseControlCharacters(path, field, number, line);
    std::istringstream tokens(line);
    std::string keyword;
    tokens >> keyword;
    if (keyword == "outer") corners = 0;
    if (keyword == "vertex" && ++corners > 3)
      throw InputError(path, field, At(number, line) + ": a facet's fourth vertex; expected three (triangulate it first)");
    if (keyword == "endloop" && corners != 3)
      throw InputError(path, field, At(number, line) + ": a facet of " + std::to_string(corners) + " vertices; expected three");
  }
}

}  // namespace

void CheckMeshText(const std::string& path, const std::string& field) {
  const std::string extension = Lower(std::filesystem::path(path).extension().string());
  if (extension == ".obj") CheckObjLines(path, field);
  if (extension == ".ply") CheckPly(path, field);
  if (extension == ".off") CheckOff(path, field);
  if (extension == ".stl") CheckAsciiStl(path, field);
}

}  // namespace dymesh
