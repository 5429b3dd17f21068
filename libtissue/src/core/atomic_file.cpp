#include "tissue/core/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

namespace tissue {
namespace {

std::string systemError(const std::string& what, const std::filesystem::path& path) {
  return what + " '" + path.string() + "': " + std::strerror(errno);
}

}  // namespace

Result<void> writeFileAtomic(const std::filesystem::path& path, std::span<const std::uint8_t> bytes) {
  std::error_code ec;
  const auto parent = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  std::filesystem::create_directories(parent, ec);
  if (ec) {
    return Error{"cannot create folder '" + parent.string() + "': " + ec.message() +
                 "; choose an output path in a writable folder"};
  }
  // A unique temporary name in the same folder, so the final rename cannot cross filesystems.
  std::random_device rd;
  // (Built with append, not operator+: g++ 12 reports a false -Wrestrict on "." + string.)
  std::string tmpName(".");
  tmpName.append(path.filename().string()).append(".tmp").append(std::to_string(rd()));
  const auto tmp = parent / tmpName;
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) return Error{systemError("cannot write", tmp) + "; check the folder's permissions"};
  std::size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n < 0) {
      if (errno == EINTR) continue;
      auto err = systemError("cannot write", tmp);
      ::close(fd);
      ::unlink(tmp.c_str());
      return Error{err + "; check free disk space"};
    }
    written += std::size_t(n);
  }
  if (::fsync(fd) != 0 || ::close(fd) != 0) {
    auto err = systemError("cannot flush", tmp);
    ::unlink(tmp.c_str());
    return Error{err + "; check free disk space"};
  }
  if (::rename(tmp.c_str(), path.c_str()) != 0) {
    auto err = systemError("cannot rename temporary file onto", path);
    ::unlink(tmp.c_str());
    return Error{err};
  }
  return {};
}

Result<void> writeTextFileAtomic(const std::filesystem::path& path, std::string_view text) {
  return writeFileAtomic(path, std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
}

Result<std::string> readTextFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Error{"cannot open '" + path.string() + "': " + std::strerror(errno)};
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace tissue
