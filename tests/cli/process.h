#pragma once
// Runs programs for the CLI tests: arguments as a list (no shell), stdout and stderr to files,
// a time limit, the exit code (128 + signal when killed by one).
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

extern char** environ;

namespace dymesh::testing {

/// A started program and where its output goes.
struct Process {
  pid_t pid = -1;
  std::filesystem::path out, err;
};

/// Whole file as text ("" when missing).
inline std::string ReadFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// Starts `argv` with stdin from /dev/null and stdout, stderr into `out`, `err`.
inline Process StartProcess(const std::vector<std::string>& argv, const std::filesystem::path& out,
                            const std::filesystem::path& err) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  Process p{-1, out, err};
  if (posix_spawnp(&p.pid, args[0], &actions, nullptr, args.data(), environ) != 0) p.pid = -1;
  posix_spawn_file_actions_destroy(&actions);
  return p;
}

/// Waits at most `seconds` (then kills it): exit code, 128 + signal if a signal ended it, -1 on failure.
inline int WaitProcess(const Process& p, double seconds) {
  if (p.pid < 0) return -1;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  int status = 0;
  while (waitpid(p.pid, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > deadline) {
      kill(p.pid, SIGKILL);
      waitpid(p.pid, &status, 0);
      return -1;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return -1;
}

/// What a finished program printed and returned.
struct ProcessResult {
  int exit_code = -1;
  std::string out, err;
};

/// Runs `argv` to its end (at most `seconds`), output captured in files under `dir`.
inline ProcessResult RunProcess(const std::vector<std::string>& argv, const std::filesystem::path& dir,
                                double seconds = 120.0) {
  std::filesystem::create_directories(dir);
  const Process p = StartProcess(argv, dir / "stdout.txt", dir / "stderr.txt");
  ProcessResult r;
  r.exit_code = WaitProcess(p, seconds);
  r.out = ReadFile(p.out);
  r.err = ReadFile(p.err);
  return r;
}

/// A program found on PATH ("" when none).
inline std::string FindOnPath(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::stringstream ss(path ? path : "");
  for (std::string dir; std::getline(ss, dir, ':');) {
    const std::filesystem::path candidate = std::filesystem::path(dir) / name;
    if (access(candidate.c_str(), X_OK) == 0) return candidate.string();
  }
  return {};
}

}  // namespace dymesh::testing
