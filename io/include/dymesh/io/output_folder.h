#pragma once
#include <stdexcept>
#include <string>
#include <vector>

/// An output folder held by one run: checked before the run, locked for its whole length, and
/// cleaned of the files the previous run recorded in its manifest (and of no others).
namespace dymesh {

/// Another process holds the folder's lock.
class OutputFolderBusy : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Hidden files of the folder: the lock and the list of files the last run wrote.
inline constexpr const char* kLockFileName = ".dymesh.lock";
inline constexpr const char* kManifestFileName = ".dymesh-manifest";

class OutputFolder {
 public:
  /// Creates `dir` when missing, checks that it is a writable folder, that every name of `outputs`
  /// (plain file names) fits its name and path limits with the temporary suffix, and that no output
  /// would replace one of `inputs` (the files the run reads), a file that is not a regular file (a
  /// FIFO would block the run), or a file no earlier dymesh run wrote (not in its manifest), and
  /// takes an exclusive lock on it. Throws InputError naming the folder, `field` (the argument the
  /// folder was given as: the command line's "--out", a library call's parameter), the file and the
  /// reason, or OutputFolderBusy when another run holds it.
  OutputFolder(const std::string& dir, std::vector<std::string> outputs, std::vector<std::string> inputs = {},
               std::string field = "--out");
  ~OutputFolder();  ///< releases the lock; removes the folder if it created it and nothing but the lock is in it
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  /// Removes the regular files named by the previous run's manifest (plain names only), then
  /// records this run's outputs as the manifest. Call just before writing the outputs.
  void ReplacePreviousRun();

  /// Records this run's outputs as the manifest and removes nothing: for an ensemble, whose earlier
  /// records in the folder are read back to resume. Call before writing any output.
  void RecordOutputs();

  const std::string& dir() const { return dir_; }

  /// The lock file's path, and the folders this run created, innermost first (none when the folder
  /// existed): what a process stopped before its first output removes (the lock, then each folder
  /// while it is empty), from a signal handler if need be.
  std::string LockPath() const;
  std::vector<std::string> CreatedFolders() const;

 private:
  void TakeFolder();  // checks the folder and takes its lock

  std::string dir_;
  std::vector<std::string> outputs_, inputs_;
  std::string field_;
  std::string created_;  // the outermost folder this run created (empty: the folder existed)
  int lock_fd_ = -1;
};

}  // namespace dymesh
