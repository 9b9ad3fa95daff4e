#include "dymesh/io/output_folder.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>

#include "dymesh/io/atomic_file.h"
#include "dymesh/io/printable.h"
#include "dymesh/core/scenario.h"
#include "dymesh/io/scenario_json.h"

namespace dymesh {
namespace {

namespace fs = std::filesystem;

// the checks below name the folder's field as the command line's; OutputFolder names its own
constexpr const char* kOutField = "--out";

[[noreturn]] void Refuse(const std::string& dir, const std::string& why) { throw InputError(dir, kOutField, why); }

// a refusal `e` of the checks below, the folder named as `field` instead
InputError AsField(const InputError& e, const std::string& field) {
  const std::string why = std::string(e.what()).substr(e.file().size() + e.field().size() + 4);
  return InputError(e.file(), field, why);
}

// dir as an absolute path without "." or "..", nor a trailing slash
fs::path AbsoluteFolder(const std::string& dir) {
  std::error_code ec;
  fs::path folder = fs::absolute(dir, ec).lexically_normal();
  return folder.has_filename() ? folder : folder.parent_path();
}

// the folder exists (created when missing) and is a folder; returns the outermost folder it
// created (empty: none)
std::string EnsureFolder(const std::string& dir) {
  std::error_code ec;
  const fs::file_status status = fs::status(dir, ec);
  if (status.type() == fs::file_type::not_found) {
    fs::path outermost = AbsoluteFolder(dir);
    while (outermost.has_parent_path() && outermost.parent_path() != outermost &&
           !fs::exists(outermost.parent_path(), ec))
      outermost = outermost.parent_path();
    fs::create_directories(dir, ec);
    if (ec) Refuse(dir, "cannot create the output folder: " + ec.message());
    return outermost.string();
  }
  if (ec) Refuse(dir, "cannot inspect the output folder: " + ec.message());
  if (status.type() != fs::file_type::directory) Refuse(dir, "exists and is not a folder: give a folder");
  return "";
}

// the folders this run created, when they hold nothing but its lock (refused or stopped before any
// output), are removed up to the outermost it created: a refusal leaves no folder behind
void RemoveIfUnused(const std::string& dir, const std::string& outermost) {
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir, ec))
    if (entry.path().filename() != kLockFileName) return;
  if (ec) return;
  fs::remove(fs::path(dir) / kLockFileName, ec);
  fs::path folder = AbsoluteFolder(dir);
  // fs::remove takes only an empty folder: it stops at the first one holding anything
  for (; fs::remove(folder, ec) && folder != fs::path(outermost); folder = folder.parent_path()) {
  }
}

// a file can be created in it (the same way the outputs will be)
void CheckWritable(const std::string& dir) {
  std::string probe = (fs::path(dir) / ".dymesh-probe.XXXXXX").string();
  const int fd = mkstemp(probe.data());
  if (fd < 0) Refuse(dir, std::string("the output folder is not writable: ") + std::strerror(errno));
  close(fd);
  unlink(probe.c_str());
}

// the names the run writes in the folder: its outputs, the lock and the manifest
std::vector<std::string> WrittenNames(std::vector<std::string> outputs) {
  outputs.push_back(kLockFileName);
  outputs.push_back(kManifestFileName);
  return outputs;
}

// every output name and its temporary fit the folder's name limit, and their paths the system's
// path limit (an over-long path failed only after the whole run, exit 1)
void CheckNames(const std::string& dir, const std::vector<std::string>& names) {
  const long limit = pathconf(dir.c_str(), _PC_NAME_MAX);
  const std::size_t max = limit > 0 ? static_cast<std::size_t>(limit) : 255;
  for (const std::string& name : names) {
    if (name.size() + kTemporaryNameExtra > max)
      Refuse(dir, "output file name \"" + name + "\" is " + std::to_string(name.size()) +
                      " bytes; this folder allows " + std::to_string(max - kTemporaryNameExtra) +
                      " (with the temporary suffix): shorten the body name");
    const std::size_t path = (fs::path(dir) / name).string().size() + kTemporaryNameExtra;
    if (path >= PATH_MAX)
      Refuse(dir, "the path of output \"" + name + "\" (with the temporary suffix) is " + std::to_string(path) +
                      " bytes; the system allows " + std::to_string(PATH_MAX - 1) + ": give a shorter folder path");
  }
}

// the folder holds an entry of that name (a dangling link too)
bool Holds(const std::string& dir, const std::string& name) {
  std::error_code ec;
  return fs::exists(fs::symlink_status(fs::path(dir) / name, ec));
}

// no name the run writes is a FIFO, a folder, a device or a socket: opening a FIFO blocks the run,
// and the others cannot be replaced
void RefuseNonRegularFiles(const std::string& dir, const std::vector<std::string>& names) {
  for (const std::string& name : names) {
    if (!Holds(dir, name)) continue;
    const std::string problem = NotARegularFile((fs::path(dir) / name).string());
    if (!problem.empty() && problem != "file not found")
      Refuse(dir, "holds \"" + name + "\", " + problem + ": remove it or choose another folder");
  }
}

// the names the folder's manifest lists (none without a manifest)
std::set<std::string> ManifestNames(const std::string& dir) {
  std::ifstream in(fs::path(dir) / kManifestFileName);
  std::set<std::string> names;
  for (std::string name; std::getline(in, name);) names.insert(name);
  return names;
}

// `file` is one of the inputs (the same file, however its path is spelt or linked)
bool IsInput(const fs::path& file, const std::vector<std::string>& inputs) {
  std::error_code ec;
  return std::any_of(inputs.begin(), inputs.end(), [&](const std::string& input) { return fs::equivalent(file, input, ec); });
}

// no name the run writes replaces a file the run reads (a scenario saved as summary.json, a mesh
// named like a deformed mesh, an ensemble's base scenario named samples.jsonl)
void RefuseReplacedInputs(const std::string& dir, const std::vector<std::string>& names, const std::vector<std::string>& inputs) {
  for (const std::string& name : names)
    if (Holds(dir, name) && IsInput(fs::path(dir) / name, inputs))
      Refuse(dir, "the output \"" + name + "\" would replace an input file of this run: move the input out of the "
                  "folder or choose another folder");
}

// an output name held by a file no earlier dymesh run listed in the manifest is the user's: replacing
// (or, for an ensemble's journal, deleting) it would lose it
void RefuseUnrecordedFiles(const std::string& dir, const std::vector<std::string>& outputs) {
  const std::set<std::string> recorded = ManifestNames(dir);
  for (const std::string& name : outputs)
    if (Holds(dir, name) && !recorded.count(name))
      Refuse(dir, "holds \"" + name + "\", which no earlier dymesh run wrote (it is not in " + kManifestFileName +
                      "): move it or choose another folder");
}

// a manifest entry dymesh may remove: a plain name in this folder, never a path, of a kind dymesh
// writes (a manifest edited to name another file does not remove it)
bool PlainName(const std::string& name) {
  const std::string extension = fs::path(name).extension().string();
  const bool ours = extension == ".json" || extension == ".csv" || extension == ".html" || extension == ".obj" ||
                    extension == ".ply" || extension == ".jsonl";
  return ours && name != "." && name != ".." && name.find('/') == std::string::npos && name != kLockFileName &&
         name != kManifestFileName;
}

// a single run's folder and an ensemble's share report.html: one kind of results per folder, so
// that neither replaces the other's report and leaves the rest
void RefuseOtherKind(const std::string& dir, const std::vector<std::string>& outputs) {
  auto has = [](const std::vector<std::string>& names, const char* name) {
    return std::find(names.begin(), names.end(), name) != names.end();
  };
  auto holds = [&](const char* name) { return Holds(dir, name); };
  const bool run = has(outputs, "summary.json"), ensemble = has(outputs, "samples.jsonl");
  if (run && (holds("samples.jsonl") || holds("samples.journal.jsonl") || holds("ensemble.json")))
    Refuse(dir, "holds an ensemble's results (samples.jsonl, ensemble.json): give another folder for a single run");
  if (ensemble && holds("summary.json"))
    Refuse(dir, "holds a single run's results (summary.json): give another folder for an ensemble");
}

}  // namespace

OutputFolder::OutputFolder(const std::string& dir, std::vector<std::string> outputs, std::vector<std::string> inputs,
                           std::string field)
    : dir_(dir), outputs_(std::move(outputs)), inputs_(std::move(inputs)), field_(std::move(field)) {
  const std::string source = field_ == kOutField ? "command line" : "argument";
  if (dir_.empty()) throw InputError(source, field_, "expected a folder name, got \"\"");
  // a library caller's string may hold a NUL, which would cut the path short
  if (dir_.find('\0') != std::string::npos)
    throw InputError(source, field_, "expected a folder name without a NUL character, got \"" + Printable(dir_) + "\"");
  try {
    created_ = EnsureFolder(dir_);
    try {
      TakeFolder();
    } catch (...) {
      if (!created_.empty()) RemoveIfUnused(dir_, created_);
      throw;
    }
  } catch (const InputError& e) {
    throw AsField(e, field_);
  }
}

void OutputFolder::TakeFolder() {
  const std::vector<std::string> names = WrittenNames(outputs_);
  CheckNames(dir_, names);
  CheckWritable(dir_);
  RefuseOtherKind(dir_, outputs_);
  RefuseNonRegularFiles(dir_, names);
  // exclusive for the whole run; the kernel releases it if the process dies
  const std::string lock = LockPath();
  lock_fd_ = open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (lock_fd_ < 0) Refuse(dir_, "cannot create the lock file " + lock + ": " + std::strerror(errno));
  if (flock(lock_fd_, LOCK_EX | LOCK_NB) != 0) {
    close(lock_fd_);
    lock_fd_ = -1;
    throw OutputFolderBusy(dir_ + ": " + field_ + ": another dymesh run is writing into this folder (it holds " + lock +
                           "): wait for it to finish or choose another folder");
  }
  // what is in the folder, once no other run changes it
  RefuseReplacedInputs(dir_, names, inputs_);
  RefuseUnrecordedFiles(dir_, outputs_);
}

OutputFolder::~OutputFolder() {
  if (!created_.empty()) RemoveIfUnused(dir_, created_);
  if (lock_fd_ >= 0) close(lock_fd_);
}

std::string OutputFolder::LockPath() const { return (fs::path(dir_) / kLockFileName).string(); }

std::vector<std::string> OutputFolder::CreatedFolders() const {
  std::vector<std::string> folders;
  if (created_.empty()) return folders;
  for (fs::path folder = AbsoluteFolder(dir_);; folder = folder.parent_path()) {
    folders.push_back(folder.string());
    if (folder == fs::path(created_) || !folder.has_parent_path() || folder.parent_path() == folder) break;
  }
  return folders;
}

void OutputFolder::ReplacePreviousRun() {
  // the previous run's files, as it recorded them; one this run reads stays
  for (const std::string& name : ManifestNames(dir_)) {
    if (!PlainName(name)) continue;
    std::error_code ec;
    const fs::path file = fs::path(dir_) / name;
    if (fs::is_regular_file(fs::symlink_status(file, ec)) && !IsInput(file, inputs_)) fs::remove(file, ec);
  }
  RecordOutputs();
}

void OutputFolder::RecordOutputs() {
  // this run's files, before any of them is written
  std::string text;
  for (const std::string& output : outputs_) text += output + "\n";
  WriteFileAtomically((fs::path(dir_) / kManifestFileName).string(), text);
}

}  // namespace dymesh
