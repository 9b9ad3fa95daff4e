#pragma once
#include <array>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "dymesh/core/options.h"
#include "dymesh/core/rigid_body.h"
#include "dymesh/core/run_status.h"
#include "dymesh/core/stiffness.h"
#include "dymesh/core/units.h"

/// The scenario: a run's definition in SI, as the JSON loader (dymesh/io/scenario_json.h) or a
/// host fills it.
namespace dymesh {

/// Unit system of a scenario's numbers (and of its outputs).
enum class UnitSystem { kSI, kUS };

/// A refused input: names the file, the JSON path of the field and what was expected.
class InputError : public std::runtime_error {
 public:
  InputError(const std::string& file, const std::string& field, const std::string& message)
      : std::runtime_error(file + ": " + field + ": " + message), file_(file), field_(field) {}
  const std::string& file() const { return file_; }
  const std::string& field() const { return field_; }

 private:
  std::string file_, field_;
};

/// Where a body's geometry comes from: a mesh file, or a generated box.
struct MeshSource {
  std::string file;                 ///< absolute path; empty for a box
  double scale = 1.0;               ///< [m per file unit] (unit and scale combined)
  std::array<std::string, 3> axes{"x", "y", "z"};  ///< body x, y, z taken from these signed mesh axes
  std::optional<double> fit_length; ///< [m] scale so the body-x extent equals this
  bool box = false;
  Vec3 box_size{0, 0, 0};           ///< [m] length, width, height
  std::array<int, 3> box_segments{1, 1, 1};
  bool cylinder = false;            ///< a generated upright cylinder (poles, trees)
  double cylinder_radius = 0.0, cylinder_height = 0.0;  ///< [m]
  int cylinder_segments = 32;       ///< facets around
  int subdivisions = 0;             ///< 1-to-4 subdivisions applied after loading
};

/// One body as the scenario describes it (SI).
struct BodySpec {
  std::string name;
  std::string vehicle_file;         ///< absolute path of the vehicle file it was read from; empty when none
  MeshSource mesh;
  std::optional<Vec3> cg;           ///< [m] CG in the mesh's body-axis coordinates; default: bounds centre
  double mass = 0.0;                ///< [kg]
  std::optional<Vec3> inertia_diagonal;  ///< [kg m^2] Ixx, Iyy, Izz; default: box of the mesh bounds
  std::array<Stiffness, kBodySurfaceCount> stiffness{};
  double restitution = 0.0;
  double friction = 0.0;
  bool rigid = false;
  MotionModel motion = MotionModel::kPlanar;
  RigidState initial;               ///< earth-frame pose and velocities at t = 0
  /// Moved at load along its velocity relative to body `with` until `gap` [m] remains (PlaceBodies).
  struct PlaceAtContact {
    int with = -1;
    double gap = 0.0;
  };
  std::optional<PlaceAtContact> place_at_contact;
};

/// A whole run.
struct Scenario {
  std::string file;                 ///< path it was read from (for messages)
  std::string name;
  UnitSystem units = UnitSystem::kSI;
  double time_step = 0.0005;        ///< [s]
  double duration = 0.25;           ///< [s]
  bool stop_at_separation = true;   ///< end once every pair has separated after contact
  bool allow_initial_overlap = false;  ///< accept bodies overlapping at t = 0 (with a warning)
  ContactOptions contact;
  std::vector<BodySpec> bodies;
  std::vector<RunWarning> warnings;  ///< implausible values and accepted oddities found at load
};

/// A length in a unit system's length unit, to 4 digits, for messages: "1.5 in", "0.04 m".
inline std::string LengthText(UnitSystem system, double metres) {
  char text[64];
  if (system == UnitSystem::kUS)
    std::snprintf(text, sizeof text, "%.4g in", metres / units::kInch);
  else
    std::snprintf(text, sizeof text, "%.4g m", metres);
  return text;
}

}  // namespace dymesh
