#include "common/safe_file.hpp"

#include "common/error.hpp"

#include <cerrno>
#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

namespace gapfem::files {
namespace {

Kind kind_of_mode(mode_t mode) {
  if (S_ISREG(mode)) return Kind::Regular;
  if (S_ISDIR(mode)) return Kind::Directory;
  if (S_ISLNK(mode)) return Kind::Symlink;
  if (S_ISFIFO(mode)) return Kind::Fifo;
  return Kind::Other;
}

[[noreturn]] void refuse(const std::filesystem::path& path, Kind kind) {
  throw AnalysisError(refusal(path, kind));
}

/// Clears O_NONBLOCK (set only so that opening a pipe cannot block) on a regular file.
void blocking(int fd) {
  const int fl = ::fcntl(fd, F_GETFL);
  if (fl >= 0) ::fcntl(fd, F_SETFL, fl & ~O_NONBLOCK);
}

bool write_fd(int fd, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd, bytes.data(), bytes.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
  return true;
}

/// Closes `fd` keeping the errno of a failure before it.
bool close_keeping(int fd, bool ok) {
  const int err = errno;
  const bool closed = ::close(fd) == 0;
  if (!ok) errno = err;
  return ok && closed;
}

/// Removes the entries of a directory of ours, not following symbolic links.
bool empty_directory(const std::filesystem::path& dir) {
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    std::filesystem::remove_all(entry.path(), ec); // removes a link, never what it points to
    if (ec) break;
  }
  if (ec) errno = ec.value();
  return !ec;
}

} // namespace

Kind kind_of(const std::filesystem::path& path) {
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0) return Kind::Missing;
  return kind_of_mode(st.st_mode);
}

const char* kind_text(Kind kind) {
  switch (kind) {
  case Kind::Missing:
    return "missing";
  case Kind::Regular:
    return "a regular file";
  case Kind::Directory:
    return "a directory";
  case Kind::Symlink:
    return "a symbolic link";
  case Kind::Fifo:
    return "a named pipe (FIFO)";
  case Kind::Other:
    break;
  }
  return "a device or socket";
}

namespace {
constexpr const char* kRefusalRemedy =
    "gapfem writes its files only as regular files it creates, never through a link or into a "
    "pipe, device or directory: remove it or choose another output directory with -o";
} // namespace

std::string refusal(const std::filesystem::path& path, Kind kind) {
  return fmt::format("'{}' is {}; {}", path.string(), kind_text(kind), kRefusalRemedy);
}

std::string refusal_reason(Kind kind) {
  return fmt::format("it is {}; {}", kind_text(kind), kRefusalRemedy);
}

int create_new(const std::filesystem::path& path) {
  for (int attempt = 0; attempt < 3; ++attempt) {
    const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd >= 0) return fd;
    if (errno != EEXIST) return -1;
    const Kind kind = kind_of(path);
    if (kind == Kind::Regular) {
      // an earlier result: unlinking it changes no other file, whatever links it has
      if (::unlink(path.c_str()) != 0 && errno != ENOENT) return -1;
    } else if (kind != Kind::Missing) {
      refuse(path, kind);
    }
  }
  errno = EEXIST; // something keeps appearing under the name
  return -1;
}

int open_own(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_RDWR | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    const int err = errno;
    const Kind kind = kind_of(path);
    if (kind != Kind::Missing && kind != Kind::Regular) refuse(path, kind);
    errno = err;
    return -1;
  }
  struct stat st {};
  if (::fstat(fd, &st) != 0) {
    close_keeping(fd, false);
    return -1;
  }
  std::string why;
  if (!S_ISREG(st.st_mode))
    why = refusal(path, kind_of_mode(st.st_mode));
  else if (st.st_nlink != 1)
    why = fmt::format("'{}' has {} names (hard links); gapfem continues only a file of its own "
                      "with one name: remove the other names or run the job from its start",
                      path.string(), st.st_nlink);
  else if (st.st_uid != ::geteuid())
    why = fmt::format("'{}' belongs to another user (uid {}); gapfem continues only files of the "
                      "user running it: remove it or run the job from its start",
                      path.string(), st.st_uid);
  if (!why.empty()) {
    ::close(fd);
    throw AnalysisError(why);
  }
  blocking(fd);
  return fd;
}

int open_read(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return -1;
  struct stat st {};
  if (::fstat(fd, &st) != 0) {
    close_keeping(fd, false);
    return -1;
  }
  if (!S_ISREG(st.st_mode)) {
    ::close(fd);
    throw AnalysisError(fmt::format("'{}' is {}, not a regular file, so it cannot be read: give "
                                    "the file itself",
                                    path.string(), kind_text(kind_of_mode(st.st_mode))));
  }
  blocking(fd);
  return fd;
}

void check_replaceable(const std::filesystem::path& path) {
  const Kind kind = kind_of(path);
  if (kind != Kind::Missing && kind != Kind::Regular) refuse(path, kind);
}

bool replace(const std::filesystem::path& from, const std::filesystem::path& to) {
  check_replaceable(to);
  return std::rename(from.c_str(), to.c_str()) == 0;
}

void remove_regular(const std::filesystem::path& path) {
  if (kind_of(path) == Kind::Regular) ::unlink(path.c_str());
}

bool write_new(const std::filesystem::path& path, std::string_view bytes) {
  const int fd = create_new(path);
  if (fd < 0) return false;
  const bool ok = write_fd(fd, bytes) && ::fsync(fd) == 0;
  return close_keeping(fd, ok);
}

bool write_replace(const std::filesystem::path& path, std::string_view bytes) {
  check_replaceable(path);
  std::filesystem::path tmp = path;
  tmp += ".tmp";
  if (!write_new(tmp, bytes)) {
    const int err = errno;
    ::unlink(tmp.c_str());
    errno = err;
    return false;
  }
  if (replace(tmp, path)) return true;
  const int err = errno;
  ::unlink(tmp.c_str());
  errno = err;
  return false;
}

bool read_all(const std::filesystem::path& path, std::string& out) {
  const int fd = open_read(path);
  if (fd < 0) return false;
  out.clear();
  char buf[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n == 0) break;
    if (n < 0) {
      if (errno == EINTR) continue;
      return close_keeping(fd, false);
    }
    out.append(buf, static_cast<std::size_t>(n));
  }
  return close_keeping(fd, true);
}

bool fresh_private_directory(const std::filesystem::path& dir) {
  if (::mkdir(dir.c_str(), 0700) == 0) return true;
  if (errno != EEXIST) return false;
  const Kind kind = kind_of(dir);
  if (kind != Kind::Directory) refuse(dir, kind);
  // opened without following a link, then checked and emptied through what was opened
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) return false;
  struct stat st {};
  if (::fstat(fd, &st) != 0) return close_keeping(fd, false);
  if (st.st_uid != ::geteuid()) {
    ::close(fd);
    throw AnalysisError(fmt::format("'{}' is a directory of another user (uid {}); gapfem "
                                    "compiles user code only in a folder of its own: remove it or "
                                    "choose another output directory with -o",
                                    dir.string(), st.st_uid));
  }
  const bool ok = ::fchmod(fd, 0700) == 0 && empty_directory(dir);
  return close_keeping(fd, ok);
}

} // namespace gapfem::files
