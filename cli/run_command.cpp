// dymesh run: simulate, report progress, write the outputs; stops cleanly when interrupted.
#include <cstdio>
#include <memory>
#include <optional>

#include <tbb/global_control.h>
#include <sstream>

#include "commands.h"
#include "format.h"
#include "dymesh/report/output_files.h"
#include "dymesh/io/body_models.h"
#include "dymesh/io/scenario_json.h"
#include "dymesh/accel/brute_force_locator.h"
#include "dymesh/accel/embree_locator.h"
#include "dymesh/accel/neighbor_box_locator.h"
#include "dymesh/io/output_folder.h"
#include "dymesh/analysis/summary.h"
#include "dymesh/core/scenario.h"
#include "dymesh/core/simulation.h"
#include "dymesh/core/units.h"
#include "placement_text.h"
#include "progress.h"

namespace dymesh::cli {
namespace {

// one line per body: the figures a reconstructionist looks at first
void PrintSummary(const Summary& s, UnitSystem system, std::ostream& out) {
  const OutputUnits u = UnitsOf(system);
  for (const BodySummary& b : s.bodies)
    out << Format("  %-16s delta-V %7.2f %s  PDOF %6.1f deg (%2d o'clock)  peak %5.1f g  max crush %6.2f %s\n",
                  b.name.c_str(), b.delta_v * u.speed, u.speed_name, b.pdof_deg, b.pdof_clock,
                  b.peak_accel / units::kStandardGravity, b.max_crush * u.length, u.length_name);
  const std::string contact =
      s.contact_start < 0.0 ? std::string("no contact") : Format("contact %.4f-%.4f s", s.contact_start, s.contact_end);
  out << Format("  %s, %d steps; energy balance error %.3f%%; node law vs crush work %+.1f%%\n", contact.c_str(),
                s.steps, 100.0 * s.energy_balance_error,
                s.crush_energy != 0.0 ? -100.0 * s.energy_discontinuity / s.crush_energy : 0.0);
}

// the list of files, and of those an interruption left unwritten
void PrintOutputs(const WrittenOutputs& w, const std::string& dir, bool quiet, std::ostream& out, std::ostream& err) {
  if (!quiet) {
    out << "outputs in " << dir << ":\n";
    for (const std::string& path : w.written) out << "  " << path << "\n";
  }
  if (w.not_written.empty()) return;
  err << "not written (interrupted):\n";
  for (const std::string& path : w.not_written) err << "  " << path << "\n";
}

// each warning on its own line: code, field, what was seen and what to do
void PrintWarnings(const Summary& s, std::ostream& err) {
  for (const RunWarning& w : s.warnings)
    err << "warning [" << w.code << "] " << (w.field.empty() ? "" : w.field + ": ") << w.message << "\n";
}

// the exit code of a run that wrote all its outputs: only a clean complete run exits 0
int ExitCodeOf(const Summary& s) {
  switch (s.status) {
    case RunStatus::kInterrupted: return kExitInterrupted;
    case RunStatus::kFailedNumerics: return kExitFailedNumerics;
    case RunStatus::kEndedInContact: return kExitEndedInContact;
    case RunStatus::kComplete: break;
  }
  return s.warnings.empty() ? kExitOk : kExitWarnings;
}

// the search the user chose; all give the same results, at different speeds
LocatorFactory MakeLocatorFactory(const std::string& name, const ContactOptions& options) {
  if (name == "neighbor_box") return accel::MakeNeighborBoxLocatorFactory(options);
  if (name == "brute_force") return accel::MakeBruteForceLocatorFactory();
  return accel::MakeEmbreeLocatorFactory(std::make_shared<const accel::EmbreeDevice>());
}

}  // namespace

int RunCommand(const RunRequest& request, const std::function<int()>& interrupts, std::ostream& out,
               std::ostream& err) {
  const Scenario scenario = LoadScenario(request.scenario_path);
  // the output folder before any work: writable, every name fits, locked for the whole run
  OutputFolder folder(request.out_dir, OutputFileNames(scenario), InputFiles(scenario));
  if (request.on_folder_taken) request.on_folder_taken(folder);
  // the thread count changes the speed only (chunked, deterministic reductions)
  std::optional<tbb::global_control> thread_limit;
  if (request.threads > 0) thread_limit.emplace(tbb::global_control::max_allowed_parallelism, request.threads);
  Simulation sim(scenario, BuildBodyModels(scenario), MakeLocatorFactory(request.locator, scenario.contact));
  if (request.on_setup_done) request.on_setup_done();
  // simulate, with progress, until done or interrupted
  ProgressReporter::Options options;
  options.terminal = request.terminal;
  std::ostringstream discard;
  ProgressReporter progress(request.quiet ? static_cast<std::ostream&>(discard) : out, scenario.duration, options);
  const bool finished = sim.Run([&](double time) {
    progress.Update(time, sim.steps());
    return interrupts() == 0;
  });
  progress.Finish();
  const int stops = interrupts();
  const Summary summary = Summarize(sim);
  if (!finished) {
    const int planned = static_cast<int>(scenario.duration / scenario.time_step + 0.5);
    err << Format("interrupted at t = %.4f s (%d of %d steps): writing the outputs of the run so far "
                  "(summary.json \"status\": \"interrupted\"); interrupt again to stop writing\n",
                  sim.time(), sim.steps(), planned);
  }
  // outputs, replacing the previous run's; a further interruption stops between files
  folder.ReplacePreviousRun();
  const WrittenOutputs written = WriteOutputs(sim, summary, request.out_dir, [&] { return interrupts() > stops; });
  if (!request.quiet) {
    out << scenario.file << ": " << scenario.name << (finished ? "" : " (interrupted)") << "\n";
    for (const PairPlacement& p : sim.placements()) out << PlacementText(sim.scenario(), p);
    PrintSummary(summary, scenario.units, out);
  }
  PrintOutputs(written, request.out_dir, request.quiet, out, err);
  if (!request.quiet || summary.status != RunStatus::kComplete)
    err << "status: " << RunStatusName(summary.status) << (summary.warnings.empty() ? "" : ", with warnings:") << "\n";
  PrintWarnings(summary, err);
  if (summary.status == RunStatus::kInterrupted || !written.not_written.empty()) {
    err << "interrupted: " << written.written.size() << " files written, " << written.not_written.size()
        << " not written\n";
    return kExitInterrupted;
  }
  return ExitCodeOf(summary);
}

}  // namespace dymesh::cli
