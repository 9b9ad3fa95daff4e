#include "dymesh/io/atomic_file.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <vector>

namespace dymesh {
namespace {

// the system's reason for the last failure, with what was being done
[[noreturn]] void Fail(const std::string& path, const std::string& what, int error, const std::string& tmp) {
  if (!tmp.empty()) std::remove(tmp.c_str());
  throw std::runtime_error("cannot write " + path + ": " + what + ": " + std::strerror(error));
}

}  // namespace

void WriteAtomically(const std::string& path, const std::function<void(std::FILE*)>& body) {
  // a unique temporary beside the target (same file system, so the rename is atomic)
  const std::filesystem::path target(path);
  std::string hidden = ".";  // built by appends: GCC 12 warns falsely on "." + string (-Wrestrict)
  hidden += target.filename().string();
  hidden += ".XXXXXX.tmp";
  const std::string pattern = (target.parent_path() / hidden).string();
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int fd = mkstemps(name.data(), 4);
  if (fd < 0) Fail(path, "cannot create a temporary file beside it", errno, "");
  const std::string tmp(name.data());
  std::FILE* f = fdopen(fd, "w");
  if (f == nullptr) {
    const int error = errno;
    close(fd);
    Fail(path, "cannot open " + tmp, error, tmp);
  }
  // the body, then flush and close, then the rename
  try {
    body(f);
  } catch (...) {
    std::fclose(f);
    std::remove(tmp.c_str());
    throw;
  }
  const bool write_error = std::ferror(f) != 0;
  const int saved = errno;
  if (std::fclose(f) != 0 || write_error) Fail(path, "write error on " + tmp, write_error ? saved : errno, tmp);
  chmod(tmp.c_str(), 0644);  // mkstemp creates 0600; outputs are for everyone to read
  if (std::rename(tmp.c_str(), path.c_str()) != 0) Fail(path, "cannot rename " + tmp, errno, tmp);
}

void WriteFileAtomically(const std::string& path, const std::string& text) {
  WriteAtomically(path, [&](std::FILE* f) { std::fwrite(text.data(), 1, text.size(), f); });
}

}  // namespace dymesh
