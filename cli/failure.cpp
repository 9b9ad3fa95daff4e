// The exception a subcommand ended on, as a message and an exit code (main's guard and an MPI rank's)
#include <cstdio>
#include <exception>

#include "commands.h"
#include "dymesh/core/scenario.h"
#include "dymesh/io/output_folder.h"

namespace dymesh::cli {

int ReportFailure() {
  try {
    throw;
  } catch (const InputError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return kExitBadInput;
  } catch (const OutputFolderBusy& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return kExitFolderBusy;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return kExitFailure;
  } catch (...) {
    std::fprintf(stderr, "error: unknown failure\n");
    return kExitFailure;
  }
}

}  // namespace dymesh::cli
