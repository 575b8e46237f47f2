#pragma once
/// @file restart_file.hpp
/// job.res, gapfem's restart file (docs/restart.md): a header naming the deck and the model's
/// fingerprint, then one self-contained record per restart point (a converged increment), each
/// with its own checksum. A run killed while writing a record leaves a damaged last record, which
/// the reader ignores: the one before it is complete.
#include "common/archive.hpp"

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace gapfem {

struct RestartHeader {
  std::string deck; ///< absolute path of the deck that wrote the file
  std::string job;
  std::uint64_t fingerprint = 0; ///< of the model (restart_fingerprint)
};

/// Where one record is in the file, and the point of the analysis it holds.
struct RestartRecordInfo {
  int step = 0;       ///< step number (1-based, as *RESTART, READ, STEP=)
  int step_index = 0; ///< index in Model::steps
  int increment = 0;  ///< completed increments of the step (INC=)
  double step_time = 0.0, total_time = 0.0;
  bool step_end = false;              ///< the last increment of the step
  std::uintmax_t offset = 0, end = 0; ///< the record's bytes in the file
};

struct RestartIndex {
  RestartHeader header;
  std::vector<RestartRecordInfo> records; ///< the complete ones, in file order
  std::uintmax_t valid_bytes = 0;         ///< end of the last complete record
};

/// Reads the header and the index of the complete records. Throws RestartDataError when the file
/// is missing or is not a gapfem restart file.
RestartIndex read_restart_index(const std::filesystem::path& path);
/// The payload of one record (checked again).
std::string read_restart_payload(const std::filesystem::path& path, const RestartRecordInfo& r);

/// Writes records. Each record is flushed and synced before write() returns.
class RestartFileWriter {
 public:
  /// Start a new file (any old one is replaced) with this header.
  void create(const std::filesystem::path& path, const RestartHeader& header);
  /// Continue a file cut to its first `keep` bytes (the records up to a restart point).
  void resume(const std::filesystem::path& path, const RestartHeader& header, std::uintmax_t keep);
  bool active() const { return !_path.empty(); }
  /// Append a record; `overlay`: the file keeps only this one (replaced atomically).
  void write(const RestartRecordInfo& info, std::string_view payload, bool overlay);
  const std::filesystem::path& path() const { return _path; }

 private:
  std::filesystem::path _path;
  RestartHeader _header;
  std::uintmax_t _size = 0;
  bool _header_written = false;
};

} // namespace gapfem
