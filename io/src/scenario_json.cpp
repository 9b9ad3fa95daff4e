#include "dymesh/io/scenario_json.h"

#include "dymesh/io/json_document.h"
#include "dymesh/io/mesh_import.h"
#include "dymesh/io/printable.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <span>
#include <sstream>
#include <string_view>
#include <utility>

#include "dymesh/core/physical_ranges.h"
#include "dymesh/core/run_start.h"
#include "dymesh/core/units.h"
#include "json_path.h"

namespace dymesh {
namespace {

using Json = nlohmann::json;
namespace fs = std::filesystem;

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kDefaultConversionHeight = 30.0 * units::kInch;  // [m] CRUSH_HEIGHT (spec §4)

// ---------------------------------------------------------------------------------------------
// unit systems: SI value = input value * factor

struct UnitScale {
  bool us = false;
  double length = 1.0;   // [m] per in | m
  double speed = 1.0;    // [m/s] per mph | m/s
  double mass = 1.0;     // [kg] per lb | kg
  double weight = 1.0;   // [kg] per lb | N (weight -> mass)
  double inertia = 1.0;  // [kg m^2] per lb in s^2 | kg m^2

  // per-area (or per-width) stiffness with length exponent n: lb/in^n -> N/m^n
  double StiffnessPow(int n) const { return us ? units::PoundPerInchPow(n) : 1.0; }
};

// conversion factors of a unit system (time is in seconds and angles in degrees in both)
UnitScale ScaleFor(UnitSystem system) {
  UnitScale s;
  if (system == UnitSystem::kUS) {
    s.us = true;
    s.length = units::kInch;
    s.speed = units::kMph;
    s.mass = units::kPoundMass;
    s.weight = units::kPoundMass;
    s.inertia = units::kPoundForce * units::kInch;
  } else {
    s.weight = 1.0 / units::kStandardGravity;
  }
  return s;
}

// where values come from: the file named in messages, its folder, its units
struct Source {
  std::string file;
  fs::path dir;
  UnitScale units;
  std::vector<RunWarning>* warnings = nullptr;  // the scenario's: implausible values land here
};

// field and message as printable text: a key or a value from the file may hold control bytes
[[noreturn]] void Fail(const Source& src, const std::string& field, const std::string& message) {
  throw InputError(src.file, Printable(field), Printable(message));
}

// ---------------------------------------------------------------------------------------------
// JSON paths and value descriptions for messages

using json_path::At;
using json_path::FieldName;
using json_path::Join;

// shortest text that reads back as the same double
std::string FormatDouble(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, res.ptr);
}

// a short description of a JSON value for "got ..."
std::string Describe(const Json& j) {
  if (j.is_object()) return "an object";
  if (j.is_array()) return "an array of " + std::to_string(j.size());
  if (j.is_number_float()) return FormatDouble(j.get<double>());
  std::string text = j.dump();
  if (text.size() > 60) text = text.substr(0, 57) + "...";
  return text;
}

// whole file as text (`ok` false when it cannot be opened)
std::string ReadTextFile(const fs::path& path, bool* ok) {
  std::ifstream in(path, std::ios::binary);
  *ok = static_cast<bool>(in);
  if (!*ok) return {};
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// ---------------------------------------------------------------------------------------------
// typed readers: each refuses a wrong type, a non-finite number or a value out of range,
// naming the field and what was expected

struct Range {
  double lo, hi;
  bool lo_open, hi_open;
  const char* text;  // appended to "expected a number"

  bool Contains(double v) const {
    const bool above = lo_open ? v > lo : v >= lo;
    const bool below = hi_open ? v < hi : v <= hi;
    return above && below;
  }
};

constexpr Range kAnyFinite{-kInfinity, kInfinity, false, false, ""};
constexpr Range kPositive{0.0, kInfinity, true, false, " > 0"};
constexpr Range kNonNegative{0.0, kInfinity, false, false, " >= 0"};
constexpr Range kUnitInterval{0.0, 1.0, false, false, " in [0, 1]"};
constexpr Range kUnitIntervalOpen{0.0, 1.0, false, true, " in [0, 1)"};

// member of an object, or nullptr when absent
const Json* Find(const Json& object, std::string_view key) {
  const auto it = object.find(key);
  return it == object.end() ? nullptr : &*it;
}

// member of an object that must be present
const Json& Require(const Source& src, const Json& object, const std::string& path, std::string_view key) {
  const Json* j = Find(object, key);
  if (j == nullptr) Fail(src, Join(path, key), "missing required key \"" + std::string(key) + "\"");
  return *j;
}

// refuses anything but a JSON object
void ExpectObject(const Source& src, const Json& j, const std::string& path) {
  if (!j.is_object()) Fail(src, FieldName(path), "expected an object, got " + Describe(j));
}

// refuses keys outside `allowed`, listing the allowed ones
void CheckKeys(const Source& src, const Json& object, const std::string& path, std::span<const std::string_view> allowed) {
  for (const auto& item : object.items()) {
    if (std::find(allowed.begin(), allowed.end(), item.key()) != allowed.end()) continue;
    std::string list;
    for (std::string_view a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
    Fail(src, Join(path, item.key()), "unknown key \"" + item.key() + "\"; allowed keys: " + list);
  }
}

void CheckKeys(const Source& src, const Json& object, const std::string& path,
               std::initializer_list<std::string_view> allowed) {
  CheckKeys(src, object, path, std::span<const std::string_view>(allowed.begin(), allowed.size()));
}

// a finite number in range (raw input units)
double ReadNumber(const Source& src, const Json& j, const std::string& path, const Range& range) {
  const std::string expected = std::string("expected a number") + range.text;
  if (!j.is_number()) Fail(src, path, expected + ", got " + Describe(j));
  const double v = j.get<double>();
  if (!std::isfinite(v)) Fail(src, path, "expected a finite number, got " + FormatDouble(v));
  if (!range.Contains(v)) Fail(src, path, expected + ", got " + Describe(j));
  return v;
}

// an integral number in lo..hi (2 and 2.0 both accepted)
int ReadInt(const Source& src, const Json& j, const std::string& path, int lo, int hi, const std::string& expected) {
  bool integral = j.is_number_integer() || j.is_number_unsigned();
  if (j.is_number_float()) {
    const double v = j.get<double>();
    integral = std::isfinite(v) && std::floor(v) == v;
  }
  if (!integral) Fail(src, path, expected + ", got " + Describe(j));
  const double v = j.get<double>();
  if (v < lo || v > hi) Fail(src, path, expected + ", got " + Describe(j));
  return static_cast<int>(v);
}

// true or false
bool ReadBool(const Source& src, const Json& j, const std::string& path) {
  if (!j.is_boolean()) Fail(src, path, "expected true or false, got " + Describe(j));
  return j.get<bool>();
}

// a JSON string
std::string ReadString(const Source& src, const Json& j, const std::string& path) {
  if (!j.is_string()) Fail(src, path, "expected a string, got " + Describe(j));
  return j.get<std::string>();
}

// one of a fixed set of strings, mapped to a value
template <typename T>
T ReadChoice(const Source& src, const Json& j, const std::string& path,
             std::initializer_list<std::pair<std::string_view, T>> choices) {
  std::string list;
  for (const auto& c : choices) list += (list.empty() ? "\"" : ", \"") + std::string(c.first) + "\"";
  if (j.is_string())
    for (const auto& c : choices)
      if (j.get<std::string>() == c.first) return c.second;
  Fail(src, path, "expected one of " + list + ", got " + Describe(j));
}

// [x, y, z], each in range (raw input units)
Vec3 ReadVec3(const Source& src, const Json& j, const std::string& path, const Range& range) {
  if (!j.is_array() || j.size() != 3) Fail(src, path, "expected an array of 3 numbers, got " + Describe(j));
  Vec3 v;
  for (int i = 0; i < 3; ++i) v[i] = ReadNumber(src, j[i], At(path, i), range);
  return v;
}

// ---------------------------------------------------------------------------------------------
// physical ranges (README "Physical ranges"): beyond the hard bounds a value is impossible and
// refused; beyond the plausible ones it is accepted with a warning naming the field. Bounds are
// SI; messages show them in the file's units.

// a unit of the file for messages: SI per unit and its name
struct InputUnit {
  double per_unit;
  const char* name;
};

InputUnit SpeedUnit(const Source& src) { return src.units.us ? InputUnit{units::kMph, "mph"} : InputUnit{1.0, "m/s"}; }
InputUnit LengthUnit(const Source& src) { return src.units.us ? InputUnit{units::kInch, "in"} : InputUnit{1.0, "m"}; }
InputUnit MassUnit(const Source& src) { return src.units.us ? InputUnit{units::kPoundMass, "lb"} : InputUnit{1.0, "kg"}; }
constexpr InputUnit kPlain{1.0, ""};

// a value in the file's units: exact for what the user wrote, 4 digits for a range bound
std::string InUnits(double si, InputUnit u, bool exact = true) {
  char rounded[32];
  std::snprintf(rounded, sizeof rounded, "%.4g", si / u.per_unit);
  return (exact ? FormatDouble(si / u.per_unit) : std::string(rounded)) +
         (u.name[0] != '\0' ? std::string(" ") + u.name : std::string());
}

// refuses an impossible value, warns on an implausible one; `si` is the converted value
void CheckPhysical(const Source& src, const std::string& field, double si, const PhysicalRange& r, InputUnit u) {
  if (si < r.hard_lo || si > r.hard_hi) {
    // the value to 4 digits, unless so rounded it would read as inside the range
    const double shown = std::strtod(InUnits(si, u, false).c_str(), nullptr) * u.per_unit;
    const bool looks_inside = shown >= r.hard_lo && shown <= r.hard_hi;
    Fail(src, field, std::string("expected a physically possible ") + r.what + " in " + InUnits(r.hard_lo, u, false) +
                         " .. " + InUnits(r.hard_hi, u, false) + ", got " + InUnits(si, u, looks_inside));
  }
  if ((si < r.lo || si > r.hi) && src.warnings != nullptr)
    src.warnings->push_back({"implausible_value", field,
                             std::string(r.what) + " " + InUnits(si, u) + " is outside the range met in vehicle "
                             "collisions, " + InUnits(r.lo, u, false) + " .. " + InUnits(r.hi, u, false) +
                             ": check the value and its unit"});
}

// a generated box's sizes, as a mesh file's built extent (CheckRunStart)
constexpr PhysicalRange kBoxRange{kBodySizeRange.hard_lo, kBodySizeRange.hard_hi, kBodySizeRange.lo, kBodySizeRange.hi,
                                  "box size"};

// a name a file can have: not empty, no NUL (a path would be cut short at it)
bool IsFileName(const std::string& name) { return !name.empty() && name.find('\0') == std::string::npos; }

// a relative path resolved against the folder of the file that names it, made absolute
std::string ResolvePath(const Source& src, const std::string& name) {
  fs::path p(name);
  if (p.is_relative()) p = src.dir / p;
  std::error_code ec;
  fs::path abs = fs::absolute(p, ec);
  return (ec ? p : abs).lexically_normal().string();
}

// absolute folder of a file (the working folder for an unnamed text)
fs::path FolderOf(const std::string& file) {
  std::error_code ec;
  if (file.empty()) return fs::current_path(ec);
  const fs::path abs = fs::absolute(fs::path(file), ec);
  return (ec ? fs::path(file) : abs).parent_path();
}

// "US" or "SI"
UnitSystem ReadUnits(const Source& src, const Json& j, const std::string& path) {
  return ReadChoice<UnitSystem>(src, j, path, {{"US", UnitSystem::kUS}, {"SI", UnitSystem::kSI}});
}

// ---------------------------------------------------------------------------------------------
// time and contact options

// "time": step, duration (seconds) and the separation stop
void ParseTime(const Source& src, const Json& j, const std::string& path, Scenario* s) {
  ExpectObject(src, j, path);
  CheckKeys(src, j, path, {"step", "duration", "stop_at_separation"});
  // step and duration in seconds in both unit systems
  s->time_step = ReadNumber(src, Require(src, j, path, "step"), Join(path, "step"), kPositive);
  s->duration = ReadNumber(src, Require(src, j, path, "duration"), Join(path, "duration"), kPositive);
  CheckPhysical(src, Join(path, "duration"), s->duration, kDurationRange, kPlain);
  if (s->time_step > s->duration)
    Fail(src, Join(path, "step"), "expected a step no longer than time.duration (" + FormatDouble(s->duration) +
                                      " s), got " + FormatDouble(s->time_step) + " s");
  if (s->duration / s->time_step > kMaxSteps)
    Fail(src, Join(path, "duration"),
         "expected at most 1e7 steps (duration / step), got " + FormatDouble(s->duration / s->time_step));
  if (const Json* v = Find(j, "stop_at_separation")) s->stop_at_separation = ReadBool(src, *v, Join(path, "stop_at_separation"));
}

// keys that act only with another option: refused where they would do nothing, or missing where it needs them
void RefuseIdleContactKeys(const Source& src, const Json& j, const std::string& path, const ContactOptions& o) {
  if (Find(j, "specified_direction") && o.search_direction != SearchDirection::kSpecified)
    Fail(src, Join(path, "specified_direction"),
         "acts only with \"search_direction\": \"specified\"; this search does not use it: remove it or set that search");
  // (fuzzing, 2026-11-27: without it the search quietly pushed along the body's -x)
  if (!Find(j, "specified_direction") && o.search_direction == SearchDirection::kSpecified)
    Fail(src, Join(path, "specified_direction"),
         "expected with \"search_direction\": \"specified\": the pushback direction in the slave's body frame, "
         "e.g. [-1, 0, 0]");
  for (const char* key : {"pushback_reduction", "pushback_reduce_limit"})
    if (Find(j, key) && o.version != 4)
      Fail(src, Join(path, key), "acts only in version 4 (pushback reduction); contact.version is " +
                                     std::to_string(o.version) + ": remove it or set \"version\": 4");
}

// "contact": every key optional, defaults from ContactOptions
void ParseContact(const Source& src, const Json& j, const std::string& path, ContactOptions* o) {
  ExpectObject(src, j, path);
  CheckKeys(src, j, path,
            {"passes_per_step", "search_direction", "specified_direction", "stop_rule", "version", "null_band",
             "pushback_reduction", "pushback_reduce_limit", "toofar_margin", "toofar_maximum", "search_backoff",
             "unload_begin", "unload_pot", "unload_stop", "max_grow_unload", "friction_null_band", "rebound_law",
             "calc_nabor_interval", "contact_tolerance", "global_search_box", "turn_within_step", "contact_normal"});
  const double length = src.units.length;
  // integers and choices
  if (const Json* v = Find(j, "passes_per_step"))
    o->passes_per_step = ReadInt(src, *v, Join(path, "passes_per_step"), 1, 1000, "expected an integer in 1..1000");
  if (const Json* v = Find(j, "search_direction"))
    o->search_direction = ReadChoice<SearchDirection>(src, *v, Join(path, "search_direction"),
                                                      {{"local_average_normal", SearchDirection::kLocalAverageNormal},
                                                       {"velocity", SearchDirection::kVelocity},
                                                       {"poly_normal", SearchDirection::kPolyNormal},
                                                       {"specified", SearchDirection::kSpecified}});
  if (const Json* v = Find(j, "stop_rule"))
    o->stop_rule = ReadChoice<StopRule>(src, *v, Join(path, "stop_rule"),
                                        {{"after_one", StopRule::kAfterOne},
                                         {"best_of_two", StopRule::kBestOfTwo},
                                         {"best_of_all", StopRule::kBestOfAll}});
  if (const Json* v = Find(j, "version")) {
    o->version = ReadInt(src, *v, Join(path, "version"), 3, 4, "expected 3 or 4");
  }
  if (const Json* v = Find(j, "rebound_law"))
    o->rebound_law = ReadChoice<ReboundLaw>(src, *v, Join(path, "rebound_law"),
                                            {{"scaled", ReboundLaw::kScaled}, {"literal", ReboundLaw::kLiteral}});
  if (const Json* v = Find(j, "turn_within_step"))
    o->turn_within_step = ReadBool(src, *v, Join(path, "turn_within_step"));
  if (const Json* v = Find(j, "contact_normal"))
    o->contact_normal = ReadChoice<ContactNormal>(src, *v, Join(path, "contact_normal"),
                                                  {{"crushed", ContactNormal::kCrushed},
                                                   {"conforming", ContactNormal::kConforming}});
  if (const Json* v = Find(j, "calc_nabor_interval"))
    o->calc_nabor_interval =
        ReadInt(src, *v, Join(path, "calc_nabor_interval"), 1, 1000000, "expected an integer >= 1");
  // the specified pushback direction, normalised
  if (const Json* v = Find(j, "specified_direction")) {
    const std::string field = Join(path, "specified_direction");
    const Vec3 d = ReadVec3(src, *v, field, kAnyFinite);
    o->specified_direction = UnitAlong(d);
    if (o->specified_direction.isZero()) Fail(src, field, "expected a vector of nonzero length, got " + FormatDouble(d.x()) + ", " + FormatDouble(d.y()) + ", " + FormatDouble(d.z()));
  }
  // lengths (>= 0; the search depths > 0)
  const std::pair<const char*, double*> lengths[] = {
      {"null_band", &o->null_band},           {"pushback_reduce_limit", &o->pushback_reduce_limit},
      {"toofar_margin", &o->toofar_margin},   {"unload_begin", &o->unload_begin},
      {"unload_pot", &o->unload_pot},         {"unload_stop", &o->unload_stop},
      {"max_grow_unload", &o->max_grow_unload}, {"contact_tolerance", &o->contact_tolerance},
      {"global_search_box", &o->global_search_box}};
  // a tuning length is a fraction of a vehicle: beyond 10 m the search rays leave float range
  constexpr double kMaxTuningLength = 10.0;  // [m]
  auto read_length = [&](const char* key, const Range& range, double* target) {
    const Json* v = Find(j, key);
    if (v == nullptr) return;
    const double si = ReadNumber(src, *v, Join(path, key), range) * length;
    if (si > kMaxTuningLength)
      Fail(src, Join(path, key), "expected a length of at most " + InUnits(kMaxTuningLength, LengthUnit(src), false) +
                                     ", got " + Describe(*v));
    *target = si;
  };
  for (const auto& [key, target] : lengths) read_length(key, kNonNegative, target);
  read_length("toofar_maximum", kPositive, &o->toofar_maximum);
  read_length("search_backoff", kPositive, &o->search_backoff);
  // fraction and speed
  if (const Json* v = Find(j, "pushback_reduction"))
    o->pushback_reduction = ReadNumber(src, *v, Join(path, "pushback_reduction"), kUnitIntervalOpen);
  if (const Json* v = Find(j, "friction_null_band"))
    o->friction_null_band = ReadNumber(src, *v, Join(path, "friction_null_band"), kNonNegative) * src.units.speed;
  RefuseIdleContactKeys(src, j, path, *o);
}

// ---------------------------------------------------------------------------------------------
// mesh source

// three signed axis names, checked by the mesh loader's own rule (IsAxesPermutation)
std::array<std::string, 3> ReadAxes(const Source& src, const Json& j, const std::string& path) {
  if (!j.is_array() || j.size() != 3) Fail(src, path, std::string(kAxesExpected) + ", got " + Describe(j));
  std::array<std::string, 3> axes;
  for (int i = 0; i < 3; ++i) {
    axes[i] = ReadString(src, j[i], At(path, i));
    if (SignedAxisIndex(axes[i]) < 0)
      Fail(src, At(path, i), "expected one of \"x\", \"-x\", \"y\", \"-y\", \"z\", \"-z\", got " + Describe(j[i]));
  }
  if (!IsAxesPermutation(axes)) Fail(src, path, std::string(kAxesExpected) + ", got " + j.dump());
  return axes;
}

// "box": sizes and grid segments of a generated box
void ParseBox(const Source& src, const Json& j, const std::string& path, MeshSource* mesh) {
  ExpectObject(src, j, path);
  CheckKeys(src, j, path, {"length", "width", "height", "segments"});
  // sizes in the file's length unit
  const char* keys[3] = {"length", "width", "height"};
  for (int i = 0; i < 3; ++i) {
    mesh->box_size[i] = ReadNumber(src, Require(src, j, path, keys[i]), Join(path, keys[i]), kPositive) * src.units.length;
    CheckPhysical(src, Join(path, keys[i]), mesh->box_size[i], kBoxRange, LengthUnit(src));
  }
  // grid segments along x, y, z
  if (const Json* v = Find(j, "segments")) {
    const std::string field = Join(path, "segments");
    if (!v->is_array() || v->size() != 3) Fail(src, field, "expected an array of 3 integers >= 1, got " + Describe(*v));
    for (int i = 0; i < 3; ++i)
      mesh->box_segments[i] = ReadInt(src, (*v)[i], At(field, i), 1, 100000, "expected an integer in 1..100000");
  }
  mesh->box = true;
}

// "cylinder": an upright pole of radius and height, facets around
void ParseCylinder(const Source& src, const Json& j, const std::string& path, MeshSource* mesh) {
  ExpectObject(src, j, path);
  CheckKeys(src, j, path, {"radius", "height", "segments"});
  mesh->cylinder_radius = ReadNumber(src, Require(src, j, path, "radius"), Join(path, "radius"), kPositive) * src.units.length;
  mesh->cylinder_height = ReadNumber(src, Require(src, j, path, "height"), Join(path, "height"), kPositive) * src.units.length;
  CheckPhysical(src, Join(path, "radius"), mesh->cylinder_radius, kBoxRange, LengthUnit(src));
  CheckPhysical(src, Join(path, "height"), mesh->cylinder_height, kBoxRange, LengthUnit(src));
  if (const Json* v = Find(j, "segments"))
    mesh->cylinder_segments = ReadInt(src, *v, Join(path, "segments"), 8, 4096, "expected an integer in 8..4096");
  mesh->cylinder = true;
}

// "mesh": a file (unit, scale, axes, fit) or a generated box, plus subdivisions
MeshSource ParseMesh(const Source& src, const Json& j, const std::string& path) {
  ExpectObject(src, j, path);
  CheckKeys(src, j, path, {"file", "unit", "scale", "axes", "fit_length", "subdivisions", "box", "cylinder"});
  MeshSource mesh;
  if (const Json* v = Find(j, "subdivisions"))
    mesh.subdivisions = ReadInt(src, *v, Join(path, "subdivisions"), 0, kMaxSubdivisions,
                                "expected an integer in 0.." + std::to_string(kMaxSubdivisions));
  // a generated cylinder takes no file or box options
  if (const Json* cylinder = Find(j, "cylinder")) {
    for (const char* key : {"file", "unit", "scale", "axes", "fit_length", "box"})
      if (Find(j, key) != nullptr) Fail(src, Join(path, key), "not allowed together with \"cylinder\"");
    ParseCylinder(src, *cylinder, Join(path, "cylinder"), &mesh);
    return mesh;
  }
  // a generated box takes no file options
  if (const Json* box = Find(j, "box")) {
    for (const char* key : {"file", "unit", "scale", "axes", "fit_length"})
      if (Find(j, key) != nullptr) Fail(src, Join(path, key), "not allowed together with \"box\"");
    ParseBox(src, *box, Join(path, "box"), &mesh);
    return mesh;
  }
  // a mesh file: must exist now, stored absolute
  const Json* file = Find(j, "file");
  if (file == nullptr) Fail(src, Join(path, "file"), "missing required key: give \"file\", \"box\" or \"cylinder\"");
  const std::string field = Join(path, "file");
  const std::string name = ReadString(src, *file, field);
  if (!IsFileName(name)) Fail(src, field, "expected a file name (no NUL character), got " + Describe(*file));
  mesh.file = ResolvePath(src, name);
  if (const std::string problem = NotARegularFile(mesh.file); !problem.empty())
    Fail(src, field, problem + ": " + mesh.file);
  // fit_length sets the size: a unit or scale beside it would do nothing
  for (const char* key : {"unit", "scale"})
    if (Find(j, "fit_length") != nullptr && Find(j, key) != nullptr)
      Fail(src, Join(path, key), "has no effect with \"fit_length\", which scales the mesh to that length: give one or the other");
  // unit times scale: metres per file unit
  double unit = 1.0;
  if (const Json* v = Find(j, "unit"))
    unit = ReadChoice<double>(src, *v, Join(path, "unit"),
                              {{"m", 1.0}, {"mm", 1e-3}, {"cm", 1e-2}, {"in", units::kInch}, {"ft", units::kFoot}});
  double scale = 1.0;
  if (const Json* v = Find(j, "scale")) scale = ReadNumber(src, *v, Join(path, "scale"), kPositive);
  mesh.scale = unit * scale;
  // axes mapping and optional fitted length
  if (const Json* v = Find(j, "axes")) mesh.axes = ReadAxes(src, *v, Join(path, "axes"));
  if (const Json* v = Find(j, "fit_length"))
    mesh.fit_length = ReadNumber(src, *v, Join(path, "fit_length"), kPositive) * src.units.length;
  return mesh;
}

// ---------------------------------------------------------------------------------------------
// stiffness

// one surface: 2-D {A, B, conversion_height} or 3-D {A3, B3, C3, D3}, plus common keys
Stiffness ParseSurfaceStiffness(const Source& src, const Json& j, const std::string& path) {
  ExpectObject(src, j, path);
  CheckKeys(src, j, path, {"A", "B", "conversion_height", "A3", "B3", "C3", "D3", "sat_crush", "max_crush", "Kv"});
  const auto& u = src.units;
  const bool has_2d = Find(j, "A") || Find(j, "B") || Find(j, "conversion_height");
  const bool has_3d = Find(j, "A3") || Find(j, "B3") || Find(j, "C3") || Find(j, "D3");
  if (has_2d && has_3d)
    Fail(src, path, "mixes 2-D keys (A, B, conversion_height) with 3-D keys (A3, B3, C3, D3); use one form");
  if (!has_2d && !has_3d)
    Fail(src, path, "expected 2-D coefficients (A, B) or 3-D coefficients (A3, B3, C3, D3)");
  auto number = [&](const char* key, const Range& range, double factor) {
    const Json* v = Find(j, key);
    return v == nullptr ? 0.0 : ReadNumber(src, *v, Join(path, key), range) * factor;
  };
  Stiffness k;
  if (has_2d) {
    // published 2-D coefficients per width, converted over the conversion height (Eq. 3)
    const double a = number("A", kNonNegative, u.StiffnessPow(1));
    const double b = number("B", kNonNegative, u.StiffnessPow(2));
    double height = kDefaultConversionHeight;
    if (const Json* v = Find(j, "conversion_height")) {
      height = ReadNumber(src, *v, Join(path, "conversion_height"), kPositive) * u.length;
      CheckPhysical(src, Join(path, "conversion_height"), height, kConversionHeightRange, LengthUnit(src));
    }
    k = StiffnessFrom2D(a, b, height);
  } else {
    // 3-D coefficients per area
    k.A = number("A3", kNonNegative, u.StiffnessPow(2));
    k.B = number("B3", kNonNegative, u.StiffnessPow(3));
    k.C = number("C3", kAnyFinite, u.StiffnessPow(4));
    k.D = number("D3", kAnyFinite, u.StiffnessPow(5));
  }
  CheckPhysical(src, Join(path, has_2d ? "A" : "A3"), k.A, kStiffnessARange, kPlain);
  CheckPhysical(src, Join(path, has_2d ? "B" : "B3"), k.B, kStiffnessBRange, kPlain);
  // saturation, maximum crush and unloading slope
  k.sat_crush = number("sat_crush", kNonNegative, u.length);
  k.max_crush = number("max_crush", kNonNegative, u.length);
  k.unload_slope = number("Kv", kNonNegative, u.StiffnessPow(3));
  if (Find(j, "Kv")) CheckPhysical(src, Join(path, "Kv"), k.unload_slope, kUnloadSlopeRange, kPlain);
  return k;
}

using SurfaceStiffness = std::array<std::optional<Stiffness>, kBodySurfaceCount>;

// the stiffness object: named surfaces, "default" for the others it names not
void ParseStiffnessSet(const Source& src, const Json& j, const std::string& path, SurfaceStiffness* out) {
  ExpectObject(src, j, path);
  CheckKeys(src, j, path, {"default", "front", "right", "back", "left", "top", "bottom"});
  std::optional<Stiffness> fallback;
  if (const Json* v = Find(j, "default")) fallback = ParseSurfaceStiffness(src, *v, Join(path, "default"));
  for (int s = 0; s < kBodySurfaceCount; ++s) {
    const char* key = BodySurfaceName(static_cast<BodySurface>(s));
    if (const Json* v = Find(j, key))
      (*out)[s] = ParseSurfaceStiffness(src, *v, Join(path, key));
    else if (fallback)
      (*out)[s] = fallback;
  }
}

// ---------------------------------------------------------------------------------------------
// bodies: fields shared by vehicle files and scenario bodies, merged vehicle first

struct BodyFields {
  std::optional<MeshSource> mesh;
  std::optional<double> mass;  // [kg] from mass or weight
  std::optional<Vec3> cg;      // [m]
  std::optional<Vec3> inertia; // [kg m^2]
  std::optional<double> restitution, friction;
  std::optional<bool> rigid;
  std::optional<MotionModel> motion;
  SurfaceStiffness stiffness;
};

// keys of BodyFields, as written
constexpr std::array<std::string_view, 11> kVehicleKeys = {
    "units", "mesh", "mass", "weight", "cg", "inertia", "restitution", "friction", "rigid", "motion", "stiffness"};
constexpr std::array<std::string_view, 13> kBodyKeys = {
    "name", "vehicle", "mesh", "mass", "weight", "cg", "inertia", "restitution", "friction", "rigid", "motion",
    "stiffness", "initial"};

// the shared keys of one object, converted with its source's units
BodyFields ParseBodyFields(const Source& src, const Json& j, const std::string& path) {
  const auto& u = src.units;
  BodyFields b;
  if (const Json* v = Find(j, "mesh")) b.mesh = ParseMesh(src, *v, Join(path, "mesh"));
  // mass or weight (not both)
  const Json* mass = Find(j, "mass");
  const Json* weight = Find(j, "weight");
  if (mass != nullptr && weight != nullptr) Fail(src, Join(path, "weight"), "give either mass or weight, not both");
  if (mass != nullptr) b.mass = ReadNumber(src, *mass, Join(path, "mass"), kPositive) * u.mass;
  if (weight != nullptr) b.mass = ReadNumber(src, *weight, Join(path, "weight"), kPositive) * u.weight;
  if (b.mass) CheckPhysical(src, Join(path, mass != nullptr ? "mass" : "weight"), *b.mass, kMassRange, MassUnit(src));
  // mass properties
  if (const Json* v = Find(j, "cg")) {
    b.cg = ReadVec3(src, *v, Join(path, "cg"), kAnyFinite) * u.length;
    for (int i = 0; i < 3; ++i) CheckPhysical(src, At(Join(path, "cg"), i), (*b.cg)[i], kCgRange, LengthUnit(src));
  }
  if (const Json* v = Find(j, "inertia")) b.inertia = ReadVec3(src, *v, Join(path, "inertia"), kPositive) * u.inertia;
  // contact properties
  if (const Json* v = Find(j, "restitution")) b.restitution = ReadNumber(src, *v, Join(path, "restitution"), kUnitInterval);
  if (const Json* v = Find(j, "friction")) {
    b.friction = ReadNumber(src, *v, Join(path, "friction"), kNonNegative);
    CheckPhysical(src, Join(path, "friction"), *b.friction, kFrictionRange, kPlain);
  }
  if (const Json* v = Find(j, "rigid")) b.rigid = ReadBool(src, *v, Join(path, "rigid"));
  if (const Json* v = Find(j, "motion"))
    b.motion = ReadChoice<MotionModel>(src, *v, Join(path, "motion"),
                                       {{"planar", MotionModel::kPlanar},
                                        {"free", MotionModel::kFree6Dof},
                                        {"gravity", MotionModel::kGravityGround},
                                        {"fixed", MotionModel::kFixed}});
  if (const Json* v = Find(j, "stiffness")) ParseStiffnessSet(src, *v, Join(path, "stiffness"), &b.stiffness);
  // a rigid body takes no crush: a stiffness beside "rigid": true would never act
  if (b.rigid.value_or(false) && Find(j, "stiffness") != nullptr)
    Fail(src, Join(path, "stiffness"), "a rigid body takes no crush, so this stiffness would never act: remove it, "
                                       "or set \"rigid\": false");
  return b;
}

// `over` wins wherever it says something
BodyFields Merge(const BodyFields& base, const BodyFields& over) {
  BodyFields m = base;
  if (over.mesh) m.mesh = over.mesh;
  if (over.mass) m.mass = over.mass;
  if (over.cg) m.cg = over.cg;
  if (over.inertia) m.inertia = over.inertia;
  if (over.restitution) m.restitution = over.restitution;
  if (over.friction) m.friction = over.friction;
  if (over.rigid) m.rigid = over.rigid;
  if (over.motion) m.motion = over.motion;
  for (int s = 0; s < kBodySurfaceCount; ++s)
    if (over.stiffness[s]) m.stiffness[s] = over.stiffness[s];
  return m;
}

// a vehicle definition file: its own units, its own paths, errors name it; *file_read gets its absolute path
BodyFields LoadVehicle(const Source& scenario, const Json& j, const std::string& path, std::string* file_read) {
  const std::string name = ReadString(scenario, j, path);
  if (!IsFileName(name))
    Fail(scenario, path, "expected a vehicle file name (no NUL character), got " + Describe(j));
  const std::string file = ResolvePath(scenario, name);
  if (const std::string problem = NotARegularFile(file); !problem.empty())
    Fail(scenario, path, problem + ": " + file);
  bool ok = false;
  const std::string text = ReadTextFile(file, &ok);
  if (!ok) Fail(scenario, path, "cannot open vehicle file: " + file);
  *file_read = file;
  try {
    const Json root = ParseJsonDocument(text, file);
    Source src{file, fs::path(file).parent_path(), {}, scenario.warnings};
    ExpectObject(src, root, "");
    CheckKeys(src, root, "", kVehicleKeys);
    src.units = ScaleFor(ReadUnits(src, Require(src, root, "", "units"), "units"));
    return ParseBodyFields(src, root, "");
  } catch (const InputError& e) {
    // the error stays the vehicle file's; it also says which scenario body uses that file
    const std::string what = e.what(), prefix = e.file() + ": " + e.field() + ": ";
    const std::string message = what.compare(0, prefix.size(), prefix) == 0 ? what.substr(prefix.size()) : what;
    throw InputError(e.file(), e.field(), message + " (the vehicle file of " + scenario.file + ": " + path + ")");
  }
}

// initial pose and velocities (earth frame, SAE)
RigidState ParseInitial(const Source& src, const Json& j, const std::string& path) {
  ExpectObject(src, j, path);
  CheckKeys(src, j, path, {"position", "heading", "roll", "pitch", "velocity", "speed", "yaw_rate", "place_at_contact"});
  const auto& u = src.units;
  RigidState r;
  r.position = ReadVec3(src, Require(src, j, path, "position"), Join(path, "position"), kAnyFinite) * u.length;
  for (int i = 0; i < 3; ++i)
    CheckPhysical(src, At(Join(path, "position"), i), r.position[i], kPositionRange, LengthUnit(src));
  // Euler angles in degrees
  auto angle = [&](const char* key, const PhysicalRange& range) {
    const Json* v = Find(j, key);
    if (v == nullptr) return 0.0;
    const double degrees = ReadNumber(src, *v, Join(path, key), kAnyFinite);
    CheckPhysical(src, Join(path, key), degrees, range, kPlain);
    return degrees * units::kDegree;
  };
  r.yaw = angle("heading", kHeadingRange);
  r.roll = angle("roll", kTiltRange);
  r.pitch = angle("pitch", kTiltRange);
  // velocity vector, or speed along the heading
  const Json* velocity = Find(j, "velocity");
  const Json* speed = Find(j, "speed");
  if (velocity != nullptr && speed != nullptr) Fail(src, Join(path, "speed"), "give either velocity or speed, not both");
  if (velocity != nullptr) {
    r.velocity = ReadVec3(src, *velocity, Join(path, "velocity"), kAnyFinite) * u.speed;
    CheckPhysical(src, Join(path, "velocity"), r.velocity.norm(), kSpeedRange, SpeedUnit(src));
  }
  if (speed != nullptr) {
    const double v = ReadNumber(src, *speed, Join(path, "speed"), kAnyFinite) * u.speed;
    CheckPhysical(src, Join(path, "speed"), v, kSpeedRange, SpeedUnit(src));
    r.velocity = Vec3(v * std::cos(r.yaw), v * std::sin(r.yaw), 0.0);
  }
  // yaw rate to body rates (p, q, r) with zero roll and pitch rates
  const double psi_dot = angle("yaw_rate", kYawRateRange);
  r.omega = Vec3(-std::sin(r.pitch), std::sin(r.roll) * std::cos(r.pitch), std::cos(r.roll) * std::cos(r.pitch)) * psi_dot;
  return r;
}

// "place_at_contact": {"with": NAME, "gap": G}; the name is resolved once every body is read
struct PlacementRequest {
  std::string with;
  double gap = 0.0;
};

std::optional<PlacementRequest> ParsePlaceAtContact(const Source& src, const Json& initial, const std::string& path) {
  const Json* j = Find(initial, "place_at_contact");
  if (j == nullptr) return std::nullopt;
  const std::string field = Join(path, "place_at_contact");
  ExpectObject(src, *j, field);
  CheckKeys(src, *j, field, {"with", "gap"});
  PlacementRequest r;
  r.with = ReadString(src, Require(src, *j, field, "with"), Join(field, "with"));
  if (const Json* v = Find(*j, "gap")) {
    r.gap = ReadNumber(src, *v, Join(field, "gap"), kNonNegative) * src.units.length;
    CheckPhysical(src, Join(field, "gap"), r.gap, kGapRange, LengthUnit(src));
  }
  return r;
}

// a planar body holds its height: a vertical velocity would be dropped (and delta-V and the energy
// balance read wrong)
void RefuseVerticalVelocityOfPlanarBody(const Source& src, const BodySpec& body, const Json& initial,
                                        const std::string& path) {
  if (body.motion != MotionModel::kPlanar || body.initial.velocity.z() == 0.0) return;
  Fail(src, At(Join(path, "velocity"), 2),
       "a body with motion \"planar\" holds its height: expected 0, got " + Describe(initial["velocity"][2]) + " " +
           SpeedUnit(src).name + " (give motion \"free\" or \"gravity\" for vertical motion)");
}

// a rigid body given a stiffness by its vehicle file (or one here, on a vehicle its file makes rigid):
// each object alone was refused that (ParseBodyFields); across the two, a vehicle file that serves other
// scenarios is kept, and the stiffness that never acts is warned
void WarnStiffnessOfRigidBody(const Source& src, const BodyFields& fields, const BodySpec& body, const std::string& path) {
  const bool stiffness = std::any_of(fields.stiffness.begin(), fields.stiffness.end(), [](const auto& k) { return k.has_value(); });
  if (!body.rigid || !stiffness || src.warnings == nullptr) return;
  src.warnings->push_back({"unused_stiffness", Join(path, "stiffness"),
                           "\"" + body.name + "\" is rigid and takes no crush, so the stiffness it has from its vehicle "
                           "file or this scenario (the one sets \"rigid\", the other the stiffness) never acts"});
}

// one scenario body: its vehicle file, its own keys, then the checks on the merged result
BodySpec ParseBody(const Source& src, const Json& j, const std::string& path) {
  ExpectObject(src, j, path);
  CheckKeys(src, j, path, kBodyKeys);
  BodySpec body;
  body.name = ReadString(src, Require(src, j, path, "name"), Join(path, "name"));
  if (body.name.empty()) Fail(src, Join(path, "name"), "expected a non-empty string, got \"\"");
  // the name becomes output file names (NAME_deformed.obj, ...)
  if (!UsableInFileNames(body.name)) Fail(src, Join(path, "name"), std::string("expected ") + kFileNameRule + ", got " + Describe(j["name"]));
  // vehicle file first, then this body's own fields
  BodyFields fields;
  if (const Json* v = Find(j, "vehicle")) fields = LoadVehicle(src, *v, Join(path, "vehicle"), &body.vehicle_file);
  fields = Merge(fields, ParseBodyFields(src, j, path));
  body.initial = ParseInitial(src, Require(src, j, path, "initial"), Join(path, "initial"));
  // geometry is required
  if (!fields.mesh) Fail(src, Join(path, "mesh"), "missing required key \"mesh\" (in the body or its vehicle file)");
  body.mesh = *fields.mesh;
  // motion, then mass (only a fixed body may go without)
  body.motion = fields.motion.value_or(MotionModel::kPlanar);
  RefuseVerticalVelocityOfPlanarBody(src, body, j["initial"], Join(path, "initial"));
  if (!fields.mass && body.motion != MotionModel::kFixed)
    Fail(src, Join(path, "mass"), "missing: give mass or weight (only a body with motion \"fixed\" may omit both)");
  body.mass = fields.mass.value_or(0.0);
  body.cg = fields.cg;
  body.inertia_diagonal = fields.inertia;
  // inertia through its radius of gyration sqrt(I / m), which must fit the body's scale
  if (fields.inertia && fields.mass)
    for (int i = 0; i < 3; ++i)
      CheckPhysical(src, At(Join(path, "inertia"), i), std::sqrt((*fields.inertia)[i] / *fields.mass),
                    kGyrationRange, LengthUnit(src));
  body.restitution = fields.restitution.value_or(0.0);
  body.friction = fields.friction.value_or(0.0);
  body.rigid = fields.rigid.value_or(false);
  WarnStiffnessOfRigidBody(src, fields, body, path);
  // stiffness: a deformable body needs A or B on every surface
  for (int s = 0; s < kBodySurfaceCount; ++s) {
    body.stiffness[s] = fields.stiffness[s].value_or(Stiffness{});
    const Stiffness& k = body.stiffness[s];
    if (!body.rigid && !(k.A > 0.0 || k.B > 0.0))
      Fail(src, Join(path, "stiffness"),
           std::string("a deformable body needs A > 0 or B > 0 on every surface; \"") + BodySurfaceName(static_cast<BodySurface>(s)) +
               "\" has none (give it, or \"default\", or set \"rigid\": true)");
  }
  return body;
}

// each place_at_contact names another body of the scenario
void ResolvePlacements(const Source& src, const std::vector<std::optional<PlacementRequest>>& requests, Scenario* s) {
  for (std::size_t i = 0; i < requests.size(); ++i) {
    if (!requests[i]) continue;
    const std::string field = Join(Join(At("bodies", i), "initial"), "place_at_contact.with");
    int with = -1;
    for (std::size_t k = 0; k < s->bodies.size(); ++k)
      if (s->bodies[k].name == requests[i]->with) with = static_cast<int>(k);
    if (with < 0) Fail(src, field, "expected the name of another body, got \"" + requests[i]->with + "\"");
    if (with == static_cast<int>(i)) Fail(src, field, "expected another body's name, got this body's own");
    s->bodies[i].place_at_contact = BodySpec::PlaceAtContact{with, requests[i]->gap};
  }
}

// refuses a scenario where nothing can crush; warns of rigid pairs (they pass through each other)
void CheckRigidBodies(const Source& src, Scenario* s) {
  const auto rigid = [](const BodySpec& b) { return b.rigid; };
  if (std::all_of(s->bodies.begin(), s->bodies.end(), rigid))
    Fail(src, "bodies", "every body is rigid: at least one must be deformable (rigid bodies take no crush, so rigid "
                        "pairs have no contact force and pass through each other)");
  for (std::size_t a = 0; a < s->bodies.size(); ++a)
    for (std::size_t b = a + 1; b < s->bodies.size(); ++b)
      if (s->bodies[a].rigid && s->bodies[b].rigid)
        s->warnings.push_back({"rigid_pair", At("bodies", b) + ".rigid",
                               "\"" + s->bodies[a].name + "\" and \"" + s->bodies[b].name +
                                   "\" are both rigid: no contact force acts between them, they pass through each other"});
}

}  // namespace

// warns of the specified search direction where it cannot serve. Between two deformable bodies one
// body-frame direction serves every body as slave, so where two cars push back along different lines
// (side, oblique and rear impacts) no one direction fits both, and one sinks into the other (a sweep of
// options, 2026-11-28: the side demo 19 in, a 45 deg impact 35 in past the struck car's crush,
// unmarked). A deformable body whose direction does not push its nodes back against its approach to
// another body looks past it and passes through it unseen (the barrier box searching along its y ran
// 2.8 m into the wall)
void WarnOfTheSpecifiedDirection(Scenario* s) {
  if (s->contact.search_direction != SearchDirection::kSpecified) return;
  const auto deformable = [](const BodySpec& b) { return !b.rigid; };
  if (std::count_if(s->bodies.begin(), s->bodies.end(), deformable) >= 2)
    s->warnings.push_back(
        {"specified_direction_shared", "contact.search_direction",
         "\"specified\" gives every body, as slave, the one direction specified_direction (in its own frame): "
         "between two deformable bodies that push back along different lines (side, oblique and rear impacts) "
         "one sinks into the other, and the crush and energies are not physical; use it head-on, or against "
         "rigid bodies"});
  for (std::size_t i = 0; i < s->bodies.size(); ++i) {
    if (s->bodies[i].rigid) continue;
    const Vec3 pushback = s->bodies[i].initial.Rotation() * s->contact.specified_direction;
    for (std::size_t j = 0; j < s->bodies.size(); ++j) {
      // closing on j (their CGs drawing together), with nodes not pushed back against that motion (at
      // 90 deg or more from it; 1e-9 of slack, so a square angle reads the same in any frame)
      const Vec3 approach = s->bodies[i].initial.velocity - s->bodies[j].initial.velocity;
      const Vec3 toward = s->bodies[j].initial.position - s->bodies[i].initial.position;
      if (j == i || !(approach.dot(toward) > 0.0) || pushback.dot(approach) < -1e-9 * approach.norm()) continue;
      s->warnings.push_back(
          {"specified_direction_away", "contact.specified_direction",
           "\"" + s->bodies[i].name + "\" approaches \"" + s->bodies[j].name + "\", but specified_direction (its " +
               "frame) does not push its nodes back against that approach: they look past \"" + s->bodies[j].name +
               "\", and the bodies pass through each other unseen; point it back along the body's approach"});
      break;
    }
  }
}

Scenario ParseScenario(const std::string& json_text, const std::string& file) {
  const Json root = ParseJsonDocument(json_text, file);
  Scenario s;
  Source src{file, FolderOf(file), {}, &s.warnings};
  ExpectObject(src, root, "");
  CheckKeys(src, root, "", {"name", "units", "time", "contact", "bodies", "allow_initial_overlap"});
  s.file = file;
  // units first: every other number depends on them
  s.units = ReadUnits(src, Require(src, root, "", "units"), "units");
  src.units = ScaleFor(s.units);
  if (const Json* v = Find(root, "name")) s.name = ReadString(src, *v, "name");
  ParseTime(src, Require(src, root, "", "time"), "time", &s);
  if (const Json* v = Find(root, "contact")) ParseContact(src, *v, "contact", &s.contact);
  if (const Json* v = Find(root, "allow_initial_overlap")) s.allow_initial_overlap = ReadBool(src, *v, "allow_initial_overlap");
  // bodies: at least two, unique names
  const Json& bodies = Require(src, root, "", "bodies");
  if (!bodies.is_array() || bodies.size() < 2)
    Fail(src, "bodies", "expected an array of at least 2 bodies, got " + Describe(bodies));
  std::vector<std::optional<PlacementRequest>> placements;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    BodySpec body = ParseBody(src, bodies[i], At("bodies", i));
    for (const BodySpec& earlier : s.bodies)
      if (earlier.name == body.name) Fail(src, Join(At("bodies", i), "name"), "duplicate body name \"" + body.name + "\"");
    s.bodies.push_back(std::move(body));
    placements.push_back(ParsePlaceAtContact(src, bodies[i]["initial"], Join(At("bodies", i), "initial")));
  }
  ResolvePlacements(src, placements, &s);
  CheckRigidBodies(src, &s);
  WarnOfTheSpecifiedDirection(&s);
  return s;
}

std::string NotARegularFile(const std::string& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  switch (status.type()) {
    case fs::file_type::regular: return "";
    case fs::file_type::not_found: return "file not found";
    case fs::file_type::directory: return "a directory, not a file";
    case fs::file_type::fifo: return "a FIFO (named pipe), not a file";
    case fs::file_type::block:
    case fs::file_type::character: return "a device, not a file";
    case fs::file_type::socket: return "a socket, not a file";
    default: return ec ? "cannot be read: " + ec.message() : "not a regular file";
  }
}

std::vector<std::string> InputFiles(const Scenario& scenario) {
  std::vector<std::string> files = {scenario.file};
  for (const BodySpec& body : scenario.bodies)
    for (const std::string& file : {body.vehicle_file, body.mesh.file})
      if (!file.empty()) files.push_back(file);
  return files;
}

Scenario LoadScenario(const std::string& path) {
  // a library caller's string may hold a NUL, which would cut the path short
  if (!IsFileName(path)) throw InputError(Printable(path), "(file)", "expected a file name (not empty, no NUL character)");
  if (const std::string problem = NotARegularFile(path); !problem.empty())
    throw InputError(path, "(file)", problem + ": " + path);
  bool ok = false;
  const std::string text = ReadTextFile(path, &ok);
  if (!ok) throw InputError(path, "(file)", "cannot open: " + path);
  return ParseScenario(text, path);
}

}  // namespace dymesh
