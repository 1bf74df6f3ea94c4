#include "output_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace gen_hazards {

namespace {

/// Temporary names tried before giving up (each is `<FILE>.tmp.<pid>.<n>`; a clash needs a
/// stale file from an earlier process with the same id).
constexpr int kMaxTemporaryNames = 100;
/// Permissions before the umask, as for any file a shell redirection creates.
constexpr mode_t kNewFileMode = 0666;

std::string failure(const std::string& what, const std::string& path, int error) {
  return "cannot " + what + " '" + path + "': " + std::strerror(error);
}

bool write_all(int fd, const std::string& text) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace

std::optional<std::string> write_file_atomically(const std::string& path, const std::string& text) {
  std::string temporary;
  int fd = -1;
  for (int n = 0; n < kMaxTemporaryNames && fd < 0; ++n) {
    temporary = path + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(n);
    fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, kNewFileMode);
    if (fd < 0 && errno != EEXIST) break;
  }
  if (fd < 0) return failure("create a temporary file next to", path, errno);

  std::optional<std::string> error;
  if (!write_all(fd, text)) {
    error = failure("write", temporary, errno);
  } else if (::fsync(fd) != 0) {
    error = failure("flush", temporary, errno);
  }
  if (::close(fd) != 0 && !error) error = failure("close", temporary, errno);
  if (!error && std::rename(temporary.c_str(), path.c_str()) != 0) {
    error = failure("rename the temporary file to", path, errno);
  }
  if (error) ::unlink(temporary.c_str());
  return error;
}

}  // namespace gen_hazards
