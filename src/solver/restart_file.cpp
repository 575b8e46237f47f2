#include "solver/restart_file.hpp"

#include "common/safe_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

namespace gapfem {

namespace {

constexpr std::string_view kMagic = "GAPFEM-RESTART\n";
/// 2: StepChecks (in every record's step summaries) carries the relative equilibrium and heat
/// balance errors; a format-1 file is refused with "written by another version".
constexpr std::uint32_t kVersion = 2;
constexpr std::uint32_t kRecordTag = 0x44434552; // "RECD"

std::string header_bytes(const RestartHeader& h) {
  ArchiveWriter a;
  a.bytes(kMagic.data(), kMagic.size());
  a.pod(kVersion);
  a.str(h.deck);
  a.str(h.job);
  a.pod(h.fingerprint);
  const std::uint64_t sum = fnv1a(a.data());
  a.pod(sum);
  return a.take();
}

/// The fixed part of a record before its payload.
struct RecordHead { // 48 bytes, no padding
  std::uint32_t tag = kRecordTag;
  std::int32_t step = 0, step_index = 0, increment = 0;
  std::int32_t step_end = 0, reserved = 0;
  double step_time = 0.0, total_time = 0.0;
  std::uint64_t size = 0;
};

static_assert(sizeof(RecordHead) == 48);

std::string record_bytes(const RestartRecordInfo& info, std::string_view payload) {
  RecordHead h;
  h.step = info.step;
  h.step_index = info.step_index;
  h.increment = info.increment;
  h.step_end = info.step_end ? 1 : 0;
  h.step_time = info.step_time;
  h.total_time = info.total_time;
  h.size = payload.size();
  ArchiveWriter a;
  a.pod(h);
  a.bytes(payload.data(), payload.size());
  const std::uint64_t sum = fnv1a(a.data());
  a.pod(sum);
  return a.take();
}

[[noreturn]] void write_failed(const std::filesystem::path& path) {
  throw AnalysisError(fmt::format("cannot write the restart file '{}': {}; free space there or "
                                  "remove *RESTART, WRITE",
                                  path.string(), std::strerror(errno)));
}

void write_all(int fd, std::string_view bytes, const std::filesystem::path& path) {
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd, bytes.data(), bytes.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      write_failed(path);
    }
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
}

/// Replace `path` by `bytes` atomically (staged as a new file, synced, renamed).
void replace_file(const std::filesystem::path& path, std::string_view bytes) {
  if (!files::write_replace(path, bytes)) write_failed(path);
}

/// The restart file of ours, opened to be continued (a regular file of this user: never through a
/// link, never a pipe).
int open_own_or_fail(const std::filesystem::path& path) {
  const int fd = files::open_own(path);
  if (fd < 0) write_failed(path);
  return fd;
}

class FileIn {
 public:
  /// Only a regular file is opened (a pipe would block): RestartDataError otherwise.
  explicit FileIn(const std::filesystem::path& p) {
    int fd = -1;
    try {
      fd = files::open_read(p);
    } catch (const AnalysisError& e) {
      throw RestartDataError(e.what());
    }
    _f = fd >= 0 ? ::fdopen(fd, "rb") : nullptr;
    if (!_f && fd >= 0) ::close(fd);
  }
  ~FileIn() {
    if (_f) std::fclose(_f);
  }
  FileIn(const FileIn&) = delete;
  FileIn& operator=(const FileIn&) = delete;
  bool ok() const { return _f != nullptr; }
  /// Exactly n bytes, or false.
  bool read(std::string& out, std::size_t n) {
    out.resize(n);
    return n == 0 || std::fread(out.data(), 1, n, _f) == n;
  }
  std::uintmax_t tell() const { return static_cast<std::uintmax_t>(std::ftell(_f)); }
  void seek(std::uintmax_t at) { std::fseek(_f, static_cast<long>(at), SEEK_SET); }

 private:
  std::FILE* _f = nullptr;
};

/// Reads the record at the current position; false when it is missing, cut short or damaged.
bool read_record(FileIn& in, std::uintmax_t file_size, RestartRecordInfo& info,
                 std::string* payload) {
  info.offset = in.tell();
  std::string head;
  if (!in.read(head, sizeof(RecordHead))) return false;
  RecordHead h;
  std::memcpy(&h, head.data(), sizeof h);
  if (h.tag != kRecordTag || h.size > file_size - info.offset) return false;
  std::string body;
  if (!in.read(body, static_cast<std::size_t>(h.size))) return false;
  std::string tail;
  if (!in.read(tail, sizeof(std::uint64_t))) return false;
  std::uint64_t sum = 0;
  std::memcpy(&sum, tail.data(), sizeof sum);
  if (fnv1a(body, fnv1a(head)) != sum) return false;
  info.step = h.step;
  info.step_index = h.step_index;
  info.increment = h.increment;
  info.step_end = h.step_end != 0;
  info.step_time = h.step_time;
  info.total_time = h.total_time;
  info.end = in.tell();
  if (payload) *payload = std::move(body);
  return true;
}

} // namespace

RestartIndex read_restart_index(const std::filesystem::path& path) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  FileIn in(path);
  if (ec || !in.ok())
    throw RestartDataError(fmt::format("cannot read the restart file '{}': {}", path.string(),
                                       ec ? ec.message() : std::strerror(errno)));
  RestartIndex idx;
  std::string magic;
  auto foreign = [&] {
    return RestartDataError(fmt::format(
        "'{}' is not a gapfem restart file (it is written by *RESTART, WRITE; gapfem cannot "
        "read Abaqus's or CalculiX's restart files)",
        path.string()));
  };
  if (!in.read(magic, kMagic.size()) || magic != kMagic) throw foreign();
  // the header's fields, then its checksum
  std::string fixed;
  if (!in.read(fixed, sizeof(std::uint32_t) + sizeof(std::uint64_t))) throw foreign();
  std::uint32_t version = 0;
  std::memcpy(&version, fixed.data(), sizeof version);
  if (version != kVersion)
    throw RestartDataError(fmt::format("the restart file '{}' was written by another version of "
                                       "gapfem (format {}, this one reads {}); run the analysis "
                                       "from its start",
                                       path.string(), version, kVersion));
  auto read_string = [&](std::string& s, std::uint64_t n) {
    if (n > size || !in.read(s, static_cast<std::size_t>(n))) throw foreign();
  };
  std::uint64_t n = 0;
  std::memcpy(&n, fixed.data() + sizeof version, sizeof n);
  read_string(idx.header.deck, n);
  std::string len;
  if (!in.read(len, sizeof n)) throw foreign();
  std::memcpy(&n, len.data(), sizeof n);
  read_string(idx.header.job, n);
  std::string rest;
  if (!in.read(rest, 2 * sizeof(std::uint64_t))) throw foreign();
  std::memcpy(&idx.header.fingerprint, rest.data(), sizeof(std::uint64_t));
  std::uint64_t sum = 0;
  std::memcpy(&sum, rest.data() + sizeof(std::uint64_t), sizeof sum);
  if (header_bytes(idx.header) !=
      std::string_view(magic + fixed + idx.header.deck + len + idx.header.job + rest))
    throw foreign();
  (void)sum;
  idx.valid_bytes = in.tell();
  RestartRecordInfo r;
  while (idx.valid_bytes < size && read_record(in, size, r, nullptr)) {
    idx.records.push_back(r);
    idx.valid_bytes = r.end;
  }
  return idx;
}

std::string read_restart_payload(const std::filesystem::path& path, const RestartRecordInfo& r) {
  FileIn in(path);
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (!in.ok() || ec)
    throw RestartDataError(fmt::format("cannot read the restart file '{}'", path.string()));
  in.seek(r.offset);
  RestartRecordInfo again;
  std::string payload;
  if (!read_record(in, size, again, &payload))
    throw RestartDataError(
        fmt::format("the restart file '{}' changed while it was read", path.string()));
  return payload;
}

void RestartFileWriter::create(const std::filesystem::path& path, const RestartHeader& header) {
  _path = path;
  _header = header;
  const std::string h = header_bytes(header);
  replace_file(path, h);
  _size = h.size();
}

void RestartFileWriter::resume(const std::filesystem::path& path, const RestartHeader& header,
                               std::uintmax_t keep) {
  _path = path;
  _header = header;
  const int fd = open_own_or_fail(path);
  const bool cut = ::ftruncate(fd, static_cast<off_t>(keep)) == 0;
  const int err = errno;
  ::close(fd);
  errno = err;
  if (!cut) write_failed(path);
  _size = keep;
}

void RestartFileWriter::write(const RestartRecordInfo& info, std::string_view payload,
                              bool overlay) {
  if (!active()) return;
  const std::string rec = record_bytes(info, payload);
  if (overlay) {
    const std::string h = header_bytes(_header);
    replace_file(_path, h + rec);
    _size = h.size() + rec.size();
    return;
  }
  const int fd = open_own_or_fail(_path);
  if (::lseek(fd, static_cast<off_t>(_size), SEEK_SET) < 0) {
    ::close(fd);
    write_failed(_path);
  }
  try {
    write_all(fd, rec, _path);
  } catch (...) {
    // cut the partial record off (best effort: the write's own error is the one reported)
    [[maybe_unused]] const int cut = ::ftruncate(fd, static_cast<off_t>(_size));
    ::close(fd);
    throw;
  }
  ::fsync(fd);
  ::close(fd);
  _size += rec.size();
}

} // namespace gapfem
