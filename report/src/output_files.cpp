#include "dymesh/report/output_files.h"

#include <algorithm>
#include <filesystem>

#include "dymesh/io/atomic_file.h"
#include "dymesh/io/history_csv.h"
#include "dymesh/io/mesh_import.h"
#include "dymesh/io/summary_json.h"
#include "dymesh/report/colour_map.h"
#include "dymesh/report/report.h"
#include "dymesh/report/svg_plot.h"

namespace dymesh {


namespace {

// writes each file unless asked to stop, recording which were written and which not
class OutputWriter {
 public:
  explicit OutputWriter(const std::function<bool()>& stop) : stop_(stop) {}
  void Emit(const std::string& path, const std::function<void()>& write) {
    if (stop_ && stop_()) {
      out_.not_written.push_back(path);
      return;
    }
    write();
    out_.written.push_back(path);
  }
  const WrittenOutputs& result() const { return out_; }

 private:
  const std::function<bool()>& stop_;
  WrittenOutputs out_;
};

// a body's meshes: OBJ, and PLY with the crush per vertex (scenario length unit, colours on a
// scale shared by every body of the run)
void WriteBodyMeshes(const Simulation& sim, int i, const std::string& dir, double crush_scale, OutputWriter* writer) {
  const OutputUnits u = UnitsOf(sim.scenario().units);
  const BodyModel& model = sim.engine().model(i);
  TriMesh deformed{sim.engine().state(i).vertices, model.mesh.triangles};
  TriMesh undeformed = model.mesh;
  for (Vec3& p : deformed.vertices) p *= u.length;
  for (Vec3& p : undeformed.vertices) p *= u.length;
  // crush scalar and colour per vertex
  std::vector<double> crush = VertexCrush(sim, i);
  std::vector<Rgb> colours;
  for (double& c : crush) {
    colours.push_back(CrushColour(crush_scale > 0.0 ? c / crush_scale : 0.0));
    c *= u.length;
  }
  const std::string base = (std::filesystem::path(dir) / model.name).string();
  const std::string scalar = std::string("crush: permanent crush |Delta| [") + u.length_name + "], colour scale 0 to " +
                             FormatFixed(crush_scale * u.length, 3) + " " + u.length_name;
  for (const auto& [suffix, mesh] : {std::pair{"_undeformed", &undeformed}, std::pair{"_deformed", &deformed}}) {
    const std::string what = model.name + suffix + ", body frame about the CG, " + u.length_name;
    const std::string obj = base + suffix + ".obj", ply = base + suffix + ".ply";
    writer->Emit(obj, [&] { WriteObj(*mesh, obj, what); });
    writer->Emit(ply, [&] { WritePly(*mesh, crush, colours, ply, what + "\n" + scalar); });
  }
}

}  // namespace

std::vector<std::string> OutputFileNames(const Scenario& scenario) {
  std::vector<std::string> names;
  for (const BodySpec& b : scenario.bodies)
    for (const char* suffix : {"_undeformed", "_deformed"})
      for (const char* ext : {".obj", ".ply"}) names.push_back(b.name + suffix + ext);
  for (const char* name : {"history.csv", "report.html", "summary.json"}) names.push_back(name);
  return names;
}

WrittenOutputs WriteOutputs(const Simulation& sim, const Summary& summary, const std::string& dir,
                            const std::function<bool()>& stop) {
  namespace fs = std::filesystem;
  fs::create_directories(dir);
  // an earlier summary must not vouch for the files about to be replaced
  const std::string summary_path = (fs::path(dir) / "summary.json").string();
  std::error_code ec;
  fs::remove(summary_path, ec);
  // meshes (crush colours on the run's largest crush)
  OutputWriter writer(stop);
  double crush_scale = 0.0;
  for (const BodySummary& b : summary.bodies) crush_scale = std::max(crush_scale, b.max_crush);
  for (int i = 0; i < sim.engine().body_count(); ++i) WriteBodyMeshes(sim, i, dir, crush_scale, &writer);
  // time history and report, then the summary last: its presence means the outputs are complete
  const std::string history = (fs::path(dir) / "history.csv").string();
  writer.Emit(history, [&] { WriteFileAtomically(history, HistoryCsv(sim)); });
  const std::string report = (fs::path(dir) / "report.html").string();
  writer.Emit(report, [&] { WriteFileAtomically(report, ReportHtml(sim, summary)); });
  writer.Emit(summary_path, [&] {
    WriteFileAtomically(summary_path, SummaryJson(summary, sim.scenario(), OutputFileNames(sim.scenario())));
  });
  return writer.result();
}


}  // namespace dymesh
