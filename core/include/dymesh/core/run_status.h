#pragma once
#include <string>
#include <vector>

/// Whether a run's results can be trusted, and if not, why: its status and its warnings.
namespace dymesh {

/// How a run ended.
enum class RunStatus {
  kComplete,        ///< the bodies separated, or came to rest in contact with no force growing
  kEndedInContact,  ///< the duration ran out while the bodies were still pushing on each other
  kInterrupted,     ///< stopped early on request (Ctrl-C): the values cover the run so far
  kFailedNumerics,  ///< a pose or velocity went non-finite: the values are not usable
};

/// "complete", "ended_in_contact", "interrupted" or "failed_numerics".
const char* RunStatusName(RunStatus status);

/// Something a user must know before trusting a result: a short stable code, the field it concerns
/// (a scenario JSON path, or empty) and a sentence that says what was seen and what to do.
struct RunWarning {
  std::string code;
  std::string field;
  std::string message;
};

}  // namespace dymesh
