#include "dymesh/core/run_status.h"

namespace dymesh {

const char* RunStatusName(RunStatus status) {
  switch (status) {
    case RunStatus::kComplete: return "complete";
    case RunStatus::kEndedInContact: return "ended_in_contact";
    case RunStatus::kInterrupted: return "interrupted";
    case RunStatus::kFailedNumerics: return "failed_numerics";
  }
  return "failed_numerics";
}

}  // namespace dymesh
