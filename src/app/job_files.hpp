#pragma once
/// @file job_files.hpp
/// The job's place in its output directory before anything is solved: the directory checked and
/// probed, every results name checked to be absent or a regular file (never a link, pipe, device
/// or directory: common/safe_file.hpp), and the job's lock, job.lck, so that two runs of one job
/// in one folder cannot write the same files (docs/results.md).
#include <filesystem>
#include <string>

namespace gapfem {

/// Checks the job name (a plain file name), creates the output directory, probes that a new file
/// can be written there and that no results name of the job is anything but a regular file;
/// throws InputError (exit 1) before any solving when one fails.
void prepare_output(const std::filesystem::path& dir, const std::string& job);

/// job.lck in the output directory: created with O_EXCL and holding this process's id, host and
/// start, and locked (flock) for as long as the job runs, so the kernel releases it when the
/// process ends in any way. A second run of the job finds it locked and stops at once naming the
/// first; a lock file whose process has ended (killed) is taken over with a warning. Removed when
/// the job ends.
class JobLock {
 public:
  JobLock() = default;
  /// Takes the lock of `job` in `dir`; InputError (exit 1) naming the run that holds it.
  static JobLock take(const std::filesystem::path& dir, const std::string& job);
  ~JobLock();
  JobLock(JobLock&& o) noexcept : _file(std::move(o._file)), _fd(o._fd) { o._fd = -1; }
  JobLock& operator=(JobLock&& o) noexcept;
  JobLock(const JobLock&) = delete;
  JobLock& operator=(const JobLock&) = delete;
  bool held() const { return _fd >= 0; }

 private:
  void release();
  std::filesystem::path _file;
  int _fd = -1;
};

} // namespace gapfem
