// dymesh check: validates a scenario and its meshes without running.
#include <algorithm>
#include <array>
#include <cstdio>

#include "commands.h"
#include "format.h"
#include "placement_text.h"
#include "dymesh/io/body_models.h"
#include "dymesh/io/mesh_import.h"
#include "dymesh/io/scenario_json.h"
#include "dymesh/core/mesh.h"
#include "dymesh/analysis/summary.h"
#include "dymesh/core/scenario.h"
#include "dymesh/core/simulation.h"
#include "dymesh/core/time_step_guide.h"

namespace dymesh::cli {
namespace {

// median edge above which two deformable bodies, both this coarse, can pass partly through each other
// where each one's nodes miss the other's faces (README, Known limits: head-on, 30 mph each, 30 in
// offset, the NSX at 12.8 in lost 0.64 mph of its 30, refined to 1.6 in 24.4; the p406 at 1.7 in
// gives 21.0 mph, its lod6 at 5.0 in 15.0). A fine mesh against a coarse one meets it at moderate
// speeds (the p406 against the stock car's 4.5 in: the convergence rows), but the coarse side takes
// little crush where its nodes miss and the fine one can sink into it (the same pair in line from 35 mph,
// a bus of metre-wide faces: README, Known limits)
constexpr double kCoarseEdge = 3.0 * units::kInch;

// what a coarse deformable body is noted for: nothing, against another as coarse, or against a finer one
enum class CoarseNote { kNone, kCoarsePair, kAgainstFiner };

// where a body's mesh comes from
std::string SourceText(const BodySpec& body) {
  if (body.mesh.cylinder) return "generated cylinder";
  if (body.mesh.box) return "generated box";
  std::string s = body.mesh.file;
  if (body.mesh.subdivisions > 0) s += Format(" (%d subdivisions)", body.mesh.subdivisions);
  return s;
}

// counts, bounds and surfaces of one body's mesh (as the engine will use it: welded, about the CG)
// `coarse_edge`: this body's median edge [m] when it is coarser than kCoarseEdge and deformable, noted
// as `note` says
void PrintBody(const Scenario& scenario, int i, const BodyModel& model, double coarse_edge, CoarseNote note,
               std::ostream& out) {
  const OutputUnits u = UnitsOf(scenario.units);
  const MeshStats s = ComputeStats(model.mesh);
  out << Format("  body %d \"%s\": %s\n", i, model.name.c_str(), SourceText(scenario.bodies[i]).c_str());
  out << Format("    vertices %d, triangles %d, open edges %d, non-manifold edges %d, degenerate triangles %d\n",
                s.vertices, s.triangles, s.open_edges, s.nonmanifold_edges, s.degenerate_triangles);
  const Vec3 lo = s.min * u.length, hi = s.max * u.length, size = hi - lo;
  out << Format("    bounds about the CG [%s]: x %.2f..%.2f  y %.2f..%.2f  z %.2f..%.2f  (size %.2f x %.2f x %.2f)\n",
                u.length_name, lo.x(), hi.x(), lo.y(), hi.y(), lo.z(), hi.z(), size.x(), size.y(), size.z());
  // vertices per body surface (each selects its stiffness)
  std::array<int, kBodySurfaceCount> count{};
  for (BodySurface surface : model.surface) ++count[static_cast<int>(surface)];
  std::string surfaces;
  for (int k = 0; k < kBodySurfaceCount; ++k)
    surfaces += Format("%s%s %d", k ? ", " : "", BodySurfaceName(static_cast<BodySurface>(k)), count[k]);
  out << "    surfaces (vertices): " << surfaces << "\n";
  const char* rigid = model.rigid ? "rigid" : "deformable";
  if (scenario.bodies[i].motion == MotionModel::kFixed)
    out << "    fixed (does not move), " << rigid << "\n";
  else
    out << Format("    %s %.1f %s, %s\n", scenario.units == UnitSystem::kUS ? "weight" : "mass", model.mass * u.mass,
                  u.mass_name, rigid);
  // what the engine tolerates but a user should know
  if (s.nonmanifold_edges > 0)
    out << "    warning: non-manifold edges (more than two triangles on an edge): inside/outside may be ambiguous there\n";
  if (const int duplicates = CountDuplicateFaces(model.mesh); duplicates > 0)
    out << "    note: " << duplicates << " duplicated faces (on the same three vertices as another; tolerated up to 10 % of the faces)\n";
  if (s.open_edges > 0)
    out << "    note: open mesh (edges used by only one triangle): usual for display meshes\n";
  // the faces the build turned: counted again on the file's own welded mesh (the body's may be subdivided)
  if (const std::string& file = scenario.bodies[i].mesh.file; !file.empty()) {
    TriMesh as_filed = LoadMeshFile(file, "mesh.file");
    if (const int turned = OrientOutward(&as_filed); turned > 0)
      out << Format("    note: %d of the file's %zu faces are turned to face outward (wound against their neighbours, "
                    "or in a closed part wound inward: README, Mesh checks)\n", turned, as_filed.triangles.size());
  }
  // a vehicle is wider (y) than it is tall (z): a y-up mesh read without its axes lies on its side
  if (!scenario.bodies[i].mesh.file.empty() && scenario.bodies[i].motion != MotionModel::kFixed && size.z() > size.y())
    out << "    note: taller (z) than wide (y): if this is a vehicle lying on its side, set mesh.axes (a y-up mesh "
           "with its front at +x takes [\"x\", \"z\", \"-y\"])\n";
  if (note == CoarseNote::kCoarsePair)
    out << Format("    note: median edge %.2f %s: against another deformable body as coarse, nodes this far apart "
                  "miss each other's faces and the bodies can pass partly through each other (README, Known "
                  "limits); mesh.subdivisions refines it\n", coarse_edge * u.length, u.length_name);
  if (note == CoarseNote::kAgainstFiner)
    out << Format("    note: median edge %.2f %s: against a finer deformable body, nodes this far apart often miss "
                  "its faces, so this body takes little of the crush there and the other can sink into it at "
                  "higher speeds (a run marks the crush its mesh could not take where it can tell, crush_not_in_mesh, "
                  "and a body gone inside a closed one, obstacle_inside; README, Known limits); "
                  "mesh.subdivisions refines it\n",
                  coarse_edge * u.length, u.length_name);
}

}  // namespace

int CheckCommand(const std::string& scenario_path, std::ostream& out) {
  // parse (every field checked), then load and clean every mesh
  Scenario scenario = LoadScenario(scenario_path);
  const auto models = BuildBodyModels(scenario);
  // what a run refuses before its first step: a fixed body given motion, placement, the stable step
  const RunStart start = CheckRunStart(&scenario, models);
  const std::vector<PairPlacement>& placements = start.placements;
  out << scenario.file << ": " << scenario.name << "\n";
  out << Format("  units %s; time step %g s, duration %g s (%d steps)%s\n", scenario.units == UnitSystem::kUS ? "US" : "SI",
                scenario.time_step, scenario.duration, static_cast<int>(scenario.duration / scenario.time_step + 0.5),
                scenario.stop_at_separation ? ", stops at separation" : "");
  // the contact period of the stiffest pair and the step it asks for
  const TimeStepGuide& guide = start.guide;
  if (guide.bounded)
    out << Format("  contact period %.3g s (\"%s\" against \"%s\"): recommended step <= %.3g s, stable limit %.3g s%s\n",
                  guide.contact_period, models[guide.body_a]->name.c_str(), models[guide.body_b]->name.c_str(),
                  guide.recommended_step, guide.stable_limit,
                  scenario.time_step > guide.recommended_step ? "; warning: the step is coarser than recommended" : "");
  // the gravity bodies' ground support
  if (guide.ground_body >= 0)
    out << Format("  ground support under \"%s\" (motion gravity, %.0f rad/s): stable limit %.3g s\n",
                  models[guide.ground_body]->name.c_str(), guide.ground_omega, guide.ground_stable_limit);
  // the step over which the fastest pair closes by the search reach
  if (guide.fastest_a >= 0 && scenario.time_step > guide.reach_step) {
    const OutputUnits u = UnitsOf(scenario.units);
    out << Format("  warning: \"%s\" and \"%s\" close %.3g %s per step, farther than the contact search reaches "
                  "(%.3g %s): contact can be missed; use a step <= %.3g s\n",
                  models[guide.fastest_a]->name.c_str(), models[guide.fastest_b]->name.c_str(),
                  guide.relative_speed * scenario.time_step * u.length, u.length_name,
                  scenario.contact.toofar_maximum * u.length, u.length_name, guide.reach_step);
  }
  // deformable bodies coarser than kCoarseEdge, noted when there is another deformable body: as a
  // coarse pair when two or more are coarse, else against the finer ones
  std::vector<double> coarse(models.size(), 0.0);
  for (std::size_t i = 0; i < models.size(); ++i)
    if (const double edge = MedianEdgeLength(models[i]->mesh); !models[i]->rigid && edge > kCoarseEdge) coarse[i] = edge;
  const bool coarse_pair = std::count_if(coarse.begin(), coarse.end(), [](double e) { return e > 0.0; }) >= 2;
  const bool other_deformable = std::count_if(models.begin(), models.end(), [](const auto& m) { return !m->rigid; }) >= 2;
  for (int i = 0; i < static_cast<int>(models.size()); ++i) {
    const CoarseNote note = coarse[i] <= 0.0 || !other_deformable ? CoarseNote::kNone
                            : coarse_pair                        ? CoarseNote::kCoarsePair
                                                                 : CoarseNote::kAgainstFiner;
    PrintBody(scenario, i, *models[i], coarse[i], note, out);
  }
  for (const PairPlacement& p : placements) out << PlacementText(scenario, p);
  // what the scenario asks that is possible but implausible
  for (const RunWarning& w : scenario.warnings)
    out << "warning [" << w.code << "] " << (w.field.empty() ? "" : w.field + ": ") << w.message << "\n";
  out << "ok: scenario and " << models.size() << " meshes are valid" << (scenario.warnings.empty() ? "" : ", with warnings")
      << "\n";
  return scenario.warnings.empty() ? kExitOk : kExitWarnings;
}

}  // namespace dymesh::cli
