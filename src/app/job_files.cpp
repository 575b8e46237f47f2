#include "app/job_files.hpp"

#include "common/error.hpp"
#include "common/log.hpp"
#include "common/safe_file.hpp"
#include "output/output_file.hpp"

#include <array>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fmt/format.h>
#include <fstream>
#include <signal.h>
#include <string_view>
#include <sys/file.h>
#include <unistd.h>

namespace gapfem {
namespace {

namespace fs = std::filesystem;

/// The suffixes of the files a job writes under fixed names, with the names they are staged
/// under (docs/results.md).
constexpr std::array<std::string_view, 16> kSuffixes = {".dat",
                                                        ".sta",
                                                        ".msg",
                                                        ".frd",
                                                        ".results.json",
                                                        ".results.json.part",
                                                        ".results.json.a",
                                                        ".results.json.b",
                                                        ".results.json.tmp",
                                                        ".pvd",
                                                        ".pvd.tmp",
                                                        ".report.html",
                                                        ".report.html.tmp",
                                                        ".res",
                                                        ".res.tmp",
                                                        ".lck"};
/// The longest name a job adds to its own: "_<step>_<increment>.vtu.tmp" of a frame (ten digits
/// each) and the probe's ".write-test.XXXXXX" with its leading dot.
constexpr std::size_t kLongestAddition = 1 + 10 + 1 + 10 + 8;

InputError directory_error(const fs::path& dir, std::string message) {
  return InputError(SourceLocation{}, fmt::format("output directory '{}'", dir.string()),
                    std::move(message));
}

/// A job name whose files would be longer than the file system allows.
void check_name_length(const fs::path& dir, const std::string& job) {
  const long max = ::pathconf(dir.c_str(), _PC_NAME_MAX);
  const std::size_t limit = max > 0 ? static_cast<std::size_t>(max) : 255;
  if (job.size() + kLongestAddition <= limit) return;
  throw InputError(SourceLocation{}, fmt::format("job name '{}'", job),
                   fmt::format("it is {} characters long; with the endings gapfem adds to it "
                               "(up to {} characters, e.g. _12_345.vtu.tmp) its file names "
                               "would be longer than the {} characters this file system allows; "
                               "choose a shorter name with -j",
                               job.size(), kLongestAddition, limit));
}

/// What to do about a directory the probe could not write into.
std::string probe_remedy(int err) {
  if (err == ENOSPC || err == EDQUOT) return "free space there or choose another directory with -o";
  if (err == EACCES || err == EPERM || err == EROFS)
    return "make it writable or choose another directory with -o";
  if (err == ENAMETOOLONG) return "choose a shorter output directory with -o";
  return "choose another directory with -o";
}

/// Writes a new file of a fresh name into `dir` and removes it: a read-only or full directory is
/// reported now, not after the analysis.
void probe(const fs::path& dir, const std::string& job) {
  std::string name = (dir / fmt::format(".{}.write-test.XXXXXX", job)).string();
  const int fd = ::mkostemp(name.data(), O_CLOEXEC); // O_EXCL: a name nothing else had
  int err = fd < 0 ? errno : 0;
  if (fd >= 0) {
    ::close(fd);
    output::OutputFile f; // written as the results are (and as the tests' full disk sees them)
    try {
      f.open(name);
      f.write("gapfem\n");
      f.close();
    } catch (const AnalysisError&) {
      err = f.error_number();
    }
    ::unlink(name.c_str());
  }
  if (err != 0)
    throw directory_error(
        dir, fmt::format("cannot write into it: {}; {}", std::strerror(err), probe_remedy(err)));
}

/// Every results name of the job that exists must be a regular file (replaced, never followed).
void check_results_names(const fs::path& dir, const std::string& job) {
  auto check = [&](const fs::path& p, bool directory_ok) {
    const files::Kind kind = files::kind_of(p);
    if (kind == files::Kind::Missing || kind == files::Kind::Regular) return;
    if (directory_ok && kind == files::Kind::Directory) return;
    throw InputError(SourceLocation{}, fmt::format("results file '{}'", p.string()),
                     files::refusal_reason(kind));
  };
  for (std::string_view suffix : kSuffixes) check(dir / (job + std::string(suffix)), false);
  check(dir / (job + ".scratch"), true); // --user compiles there (its own checks)
  std::error_code ec;
  const std::string frame = job + "_";
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    const bool vtu = name.ends_with(".vtu") || name.ends_with(".vtu.tmp");
    if (vtu && name.starts_with(frame)) check(entry.path(), false);
  }
}

// ---------------------------------------------------------------- the lock

/// This process's start in clock ticks after boot (/proc/self/stat field 22), or 0.
unsigned long long start_ticks(long pid) {
  std::ifstream in(fmt::format("/proc/{}/stat", pid));
  std::string stat;
  if (!std::getline(in, stat)) return 0;
  const std::size_t close = stat.rfind(')'); // the command may hold blanks and parentheses
  if (close == std::string::npos) return 0;
  std::string_view rest = std::string_view(stat).substr(close + 2);
  for (int field = 3; field < 22; ++field) { // rest starts at field 3
    const std::size_t blank = rest.find(' ');
    if (blank == std::string_view::npos) return 0;
    rest.remove_prefix(blank + 1);
  }
  return std::strtoull(std::string(rest.substr(0, rest.find(' '))).c_str(), nullptr, 10);
}

std::string host_name() {
  std::array<char, 256> buf{};
  if (::gethostname(buf.data(), buf.size() - 1) != 0) return "?";
  return buf.data();
}

/// "process 1234 on host h" from a lock file's text (its first line).
std::string holder(const std::string& text) {
  long pid = 0;
  char host[256] = {};
  if (std::sscanf(text.c_str(), "gapfem pid %ld host %255s", &pid, host) == 2)
    return fmt::format("process {} on host {}", pid, host);
  return "another gapfem process";
}

std::string read_fd(int fd) {
  std::string text;
  char buf[512];
  ssize_t n = 0;
  ::lseek(fd, 0, SEEK_SET);
  while ((n = ::read(fd, buf, sizeof buf)) > 0) text.append(buf, static_cast<std::size_t>(n));
  return text;
}

/// Creates and locks a new lock file; -1 with errno when the name exists or the system refuses.
int create_locked(const fs::path& file) {
  const int fd = ::open(file.c_str(), O_RDWR | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (fd < 0) return -1;
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) { // a run that opened it between create and lock
    const int err = errno;
    ::close(fd);
    errno = err;
    return -1;
  }
  const std::string text = fmt::format("gapfem pid {} host {} start {}\n", ::getpid(), host_name(),
                                       start_ticks(::getpid()));
  if (::write(fd, text.data(), text.size()) != static_cast<ssize_t>(text.size())) {
    const int err = errno;
    ::close(fd);
    ::unlink(file.c_str());
    errno = err;
    return -1;
  }
  return fd;
}

InputError lock_error(const fs::path& file, const std::string& job, std::string message) {
  return InputError(SourceLocation{}, fmt::format("job '{}'", job), std::move(message));
}

} // namespace

void prepare_output(const fs::path& dir, const std::string& job) {
  // '/' is the only directory separator here: a backslash is a character of a Linux file name
  if (job.empty() || job == "." || job == ".." || job.find('/') != std::string::npos)
    throw InputError(SourceLocation{}, fmt::format("job name '{}'", job),
                     "a job name is a file name without a directory (job.dat, job.sta, ... are "
                     "written into the output directory); choose the directory with -o");
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    throw directory_error(dir, "it exists and is not a directory; choose another with -o");
  fs::create_directories(dir, ec);
  if (ec)
    throw directory_error(
        dir, fmt::format("cannot create it: {}; {}", ec.message(), probe_remedy(ec.value())));
  check_name_length(dir, job);
  probe(dir, job);
  check_results_names(dir, job);
}

JobLock JobLock::take(const fs::path& dir, const std::string& job) {
  JobLock lock;
  lock._file = dir / (job + ".lck");
  for (int attempt = 0; attempt < 3 && lock._fd < 0; ++attempt) {
    lock._fd = create_locked(lock._file);
    if (lock._fd >= 0) break;
    if (errno != EEXIST)
      throw lock_error(lock._file, job,
                       fmt::format("cannot create its lock file '{}': {}; check that the output "
                                   "directory is writable",
                                   lock._file.string(), std::strerror(errno)));
    const files::Kind kind = files::kind_of(lock._file);
    if (kind == files::Kind::Missing) continue; // its run ended meanwhile
    if (kind != files::Kind::Regular)
      throw lock_error(lock._file, job, files::refusal(lock._file, kind));
    const int old = ::open(lock._file.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    if (old < 0) continue;
    const std::string text = read_fd(old);
    if (::flock(old, LOCK_EX | LOCK_NB) != 0) {
      ::close(old);
      throw lock_error(lock._file, job,
                       fmt::format("it is already running in '{}' ({}; its lock file is '{}'); "
                                   "wait until it ends, or run this one with another job name "
                                   "(-j) or output directory (-o)",
                                   dir.string(), holder(text), lock._file.string()));
    }
    // the run that wrote it has ended without removing it (killed): take it over
    log::warning("Job {}: the lock file '{}' was left by {}, which no longer runs; taking it over",
                 job, lock._file.string(), holder(text));
    ::unlink(lock._file.c_str());
    ::close(old);
  }
  if (lock._fd < 0)
    throw lock_error(lock._file, job,
                     fmt::format("its lock file '{}' keeps appearing; check that no other run of "
                                 "the job uses '{}'",
                                 lock._file.string(), dir.string()));
  return lock;
}

JobLock& JobLock::operator=(JobLock&& o) noexcept {
  if (this != &o) {
    release();
    _file = std::move(o._file);
    _fd = o._fd;
    o._fd = -1;
  }
  return *this;
}

JobLock::~JobLock() {
  release();
}

void JobLock::release() {
  if (_fd < 0) return;
  ::unlink(_file.c_str()); // while still locked: a run waiting for it never sees a stale file
  ::close(_fd);
  _fd = -1;
}

} // namespace gapfem
