#include "output/output_file.hpp"

#include "common/error.hpp"
#include "common/safe_file.hpp"
#include "model/model.hpp"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fcntl.h>
#include <numeric>
#include <unistd.h>

namespace gapfem::output {

// ---------------------------------------------------------------- OutputFile

namespace {

std::atomic<long long> g_write_budget{-1}; ///< testing::limit_writes; negative: unlimited

/// fwrite with the injected limit: a write beyond the budget fails as on a full disk.
std::size_t write_limited(const void* data, std::size_t n, std::FILE* f) {
  long long budget = g_write_budget.load();
  if (budget >= 0) {
    const auto allowed = static_cast<std::size_t>(std::min<long long>(budget, n));
    g_write_budget = budget - static_cast<long long>(allowed);
    const std::size_t done = allowed > 0 ? std::fwrite(data, 1, allowed, f) : 0;
    if (allowed < n) errno = ENOSPC;
    return done;
  }
  return std::fwrite(data, 1, n, f);
}

} // namespace

void sync_directory(const std::filesystem::path& dir) {
  const int fd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

namespace testing {
void limit_writes(long long bytes) {
  g_write_budget = bytes;
}
} // namespace testing

OutputFile::~OutputFile() {
  // Destructors must not throw: write what we can and close quietly. A Replace file not closed
  // normally (an exception unwinding) is not moved over the previous complete file.
  if (_file) {
    if (_buffer.size() > 0 && !_failed) write_limited(_buffer.data(), _buffer.size(), _file);
    std::fclose(_file);
    if (_mode == Mode::Replace) {
      std::error_code ec;
      std::filesystem::remove(_staging, ec);
    }
  }
}

void OutputFile::open(const std::filesystem::path& path, Mode mode) {
  close();
  _path = path;
  _mode = mode;
  _failed = false;
  _errno = 0;
  _staging = path;
  if (mode == Mode::Replace) _staging += ".tmp";
  _buffer.clear();
  adopt(files::create_new(_staging), "wb");
}

void OutputFile::open_update(const std::filesystem::path& file, std::uintmax_t keep,
                             const std::filesystem::path& shown) {
  close();
  _path = shown;
  _staging = file;
  _mode = Mode::Update;
  _failed = false;
  _errno = 0;
  _buffer.clear();
  int fd = files::open_own(file);
  if (fd < 0 && errno == ENOENT) fd = files::create_new(file);
  adopt(fd, "r+b");
  if (::ftruncate(fileno(_file), static_cast<off_t>(keep)) != 0 ||
      std::fseek(_file, 0, SEEK_END) != 0)
    fail("cannot write");
}

void OutputFile::open_resumed(const std::filesystem::path& path,
                              const std::filesystem::path& source, std::uintmax_t keep) {
  std::error_code ec;
  const std::uintmax_t have = std::filesystem::file_size(source, ec);
  if (ec || have < keep)
    throw AnalysisError(fmt::format("the results file '{}' of the restarted job is {} than when "
                                    "its restart data was written, so it cannot be continued; "
                                    "run the analysis from its start",
                                    source.string(), ec ? "missing or unreadable" : "shorter"));
  if (path == source || std::filesystem::equivalent(path, source, ec)) {
    open_update(path, keep, path);
    return;
  }
  open(path);
  append_file_range(source, 0, keep);
}

void OutputFile::adopt(int fd, const char* mode) {
  if (fd >= 0) {
    _file = ::fdopen(fd, mode);
    if (!_file) ::close(fd);
  }
  if (!_file) fail("cannot create");
}

std::uintmax_t OutputFile::position() {
  if (!_file) return 0;
  drain();
  if (std::fflush(_file) != 0) fail("cannot write");
  const long at = std::ftell(_file);
  return at < 0 ? 0 : static_cast<std::uintmax_t>(at);
}

void OutputFile::fail(const char* what) {
  const int err = errno;
  _errno = err;
  _failed = true;
  if (_file) {
    std::fclose(_file);
    _file = nullptr;
  }
  _buffer.clear();
  std::error_code ec;
  if (_mode == Mode::Replace) std::filesystem::remove(_staging, ec);
  const bool full = err == ENOSPC || err == EDQUOT || err == EFBIG;
  throw AnalysisError(fmt::format(
      "{} results file '{}': {}; {}", what, _path.string(), std::strerror(err),
      full ? "the result files keep the increments completed before; free space and run again"
           : "check that the output directory exists, is writable and has free space"));
}

void OutputFile::put(const void* data, std::size_t n) {
  if (n > 0 && write_limited(data, n, _file) != n) fail("cannot write");
}

void OutputFile::drain() {
  if (!_file || _buffer.size() == 0) return;
  put(_buffer.data(), _buffer.size());
  _buffer.clear();
}

void OutputFile::write_bytes(const void* data, std::size_t n) {
  if (n < kChunk / 4) {
    const auto* p = static_cast<const char*>(data);
    _buffer.append(p, p + n);
    maybe_flush();
    return;
  }
  drain();
  if (_file) put(data, n);
}

void OutputFile::append_file(const std::filesystem::path& source) {
  append_file_range(source, 0, UINTMAX_MAX);
}

void OutputFile::append_file_range(const std::filesystem::path& source, std::uintmax_t from,
                                   std::uintmax_t to) {
  if (!_file || to <= from) return;
  drain();
  if (g_write_budget.load() < 0 && copy_in_kernel(source, from, to)) return;
  const int in_fd = files::open_read(source);
  std::FILE* in = in_fd >= 0 ? ::fdopen(in_fd, "rb") : nullptr;
  if (!in) {
    if (in_fd >= 0) ::close(in_fd);
    fail("cannot read the staged part of the");
  }
  if (from > 0 && std::fseek(in, static_cast<long>(from), SEEK_SET) != 0) {
    std::fclose(in);
    fail("cannot read the staged part of the");
  }
  std::vector<char> chunk(kChunk);
  std::uintmax_t left = to - from;
  std::size_t got = 0;
  while (left > 0 &&
         (got = std::fread(chunk.data(), 1,
                           static_cast<std::size_t>(std::min<std::uintmax_t>(chunk.size(), left)),
                           in)) > 0) {
    left -= got;
    if (write_limited(chunk.data(), got, _file) != got) {
      std::fclose(in);
      fail("cannot write");
    }
  }
  const bool bad = std::ferror(in) != 0;
  std::fclose(in);
  if (bad) fail("cannot read the staged part of the");
}

bool OutputFile::copy_in_kernel(const std::filesystem::path& source, std::uintmax_t from,
                                std::uintmax_t to) {
  // copy_file_range: the bytes move inside the kernel (no round trip through this process)
  if (std::fflush(_file) != 0) fail("cannot write");
  const int in = files::open_read(source);
  if (in < 0) fail("cannot read the staged part of the");
  auto off = static_cast<off_t>(from);
  const int out = fileno(_file);
  bool done = true;
  while (static_cast<std::uintmax_t>(off) < to) {
    const auto want = static_cast<std::size_t>(
        std::min<std::uintmax_t>(to - static_cast<std::uintmax_t>(off), std::uintmax_t{1} << 30));
    const ssize_t n = ::copy_file_range(in, &off, out, nullptr, want, 0);
    if (n > 0) continue;
    if (n == 0) break; // the end of the source
    const int err = errno;
    if (err == EXDEV || err == ENOSYS || err == EINVAL || err == EOPNOTSUPP) {
      // not available here: the caller copies through a buffer (only if nothing was copied)
      done = static_cast<std::uintmax_t>(off) != from;
      if (!done) break;
    }
    ::close(in);
    errno = err;
    fail("cannot write");
  }
  ::close(in);
  if (done && std::fseek(_file, 0, SEEK_END) != 0) fail("cannot write");
  return done;
}

void OutputFile::flush() {
  drain();
  if (_file && std::fflush(_file) != 0) fail("cannot write");
}

void OutputFile::close() {
  if (!_file) return;
  drain();
  if (std::fflush(_file) != 0) fail("cannot write");
  // fdatasync: the data and what is needed to read it back (the size), without the times
  if (_mode != Mode::InPlace && ::fdatasync(fileno(_file)) != 0) fail("cannot write");
  const int rc = std::fclose(_file);
  _file = nullptr;
  if (rc != 0) fail("cannot close");
  if (_mode != Mode::Replace) return;
  bool replaced = false;
  try {
    replaced = files::replace(_staging, _path);
  } catch (...) { // _path is not a file gapfem may replace: the staged copy goes
    std::error_code ec;
    std::filesystem::remove(_staging, ec);
    throw;
  }
  if (!replaced) fail("cannot replace");
  sync_directory(_path.parent_path());
}

// ---------------------------------------------------------------- formatting

std::string spaced(std::string_view text) {
  std::string out;
  out.reserve(text.size() * 2 + 4);
  bool first = true;
  for (char c : text) {
    if (c == ' ') {
      if (!out.empty() && out.back() != ' ') out += "   "; // words: three blanks
      continue;
    }
    if (!first && out.back() != ' ') out += ' ';
    out += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    first = false;
  }
  return out;
}

void append_energies(fmt::memory_buffer& out, const Energies& e) {
  const std::pair<std::string_view, double> terms[] = {
      {"ALLKE", e.allke}, {"ALLIE", e.allie}, {"ALLVD", e.allvd}, {"ALLFD", e.allfd},
      {"ALLSD", e.allsd}, {"ALLKL", e.allkl}, {"ALLWK", e.allwk}, {"ETOTAL", e.etotal()},
      {"ALLSE", e.allse}, {"ALLAE", e.allae}};
  out.append(std::string_view(",\"energies\":{"));
  bool first = true;
  for (const auto& [name, v] : terms) {
    if (!first) out.push_back(',');
    first = false;
    out.push_back('"');
    out.append(name);
    out.append(std::string_view("\":"));
    append_json_number(out, v);
  }
  out.push_back('}');
}

void append_json_number(fmt::memory_buffer& out, double v) {
  if (!std::isfinite(v)) {
    out.append(std::string_view("null"));
    return;
  }
  fmt::format_to(std::back_inserter(out), "{}",
                 v); // shortest round-trip representation
}

void append_json_key(fmt::memory_buffer& b, std::string_view k) {
  b.push_back('"');
  b.append(k);
  b.append(std::string_view("\":"));
}

void append_json_field(fmt::memory_buffer& b, std::string_view k, double v) {
  b.push_back(',');
  append_json_key(b, k);
  append_json_number(b, v);
}

void append_json_array(fmt::memory_buffer& out, std::span<const double> values) {
  out.push_back('[');
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i) out.push_back(',');
    append_json_number(out, values[i]);
  }
  out.push_back(']');
}

void append_xml_text(fmt::memory_buffer& out, std::string_view s) {
  for (char c : s) {
    switch (c) {
    case '&':
      out.append(std::string_view("&amp;"));
      break;
    case '<':
      out.append(std::string_view("&lt;"));
      break;
    case '>':
      out.append(std::string_view("&gt;"));
      break;
    case '"':
      out.append(std::string_view("&quot;"));
      break;
    case '\'':
      out.append(std::string_view("&apos;"));
      break;
    default:
      out.push_back(c);
    }
  }
}

namespace {
/// Length of a valid UTF-8 sequence starting at s[i], or 0 if the bytes there
/// are not valid.
std::size_t utf8_length(std::string_view s, std::size_t i) {
  const auto b0 = static_cast<unsigned char>(s[i]);
  std::size_t n = 0;
  if (b0 >= 0xC2 && b0 <= 0xDF)
    n = 2;
  else if (b0 >= 0xE0 && b0 <= 0xEF)
    n = 3;
  else if (b0 >= 0xF0 && b0 <= 0xF4)
    n = 4;
  else
    return 0;
  if (i + n > s.size()) return 0;
  for (std::size_t k = 1; k < n; ++k)
    if ((static_cast<unsigned char>(s[i + k]) & 0xC0) != 0x80) return 0;
  const auto b1 = static_cast<unsigned char>(s[i + 1]);
  if (b0 == 0xE0 && b1 < 0xA0) return 0; // overlong
  if (b0 == 0xED && b1 > 0x9F) return 0; // surrogates
  if (b0 == 0xF0 && b1 < 0x90) return 0; // overlong
  if (b0 == 0xF4 && b1 > 0x8F) return 0; // > U+10FFFF
  return n;
}
} // namespace

void append_json_string(fmt::memory_buffer& out, std::string_view s) {
  out.push_back('"');
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c < 0x80) {
      switch (c) {
      case '"':
        out.append(std::string_view("\\\""));
        break;
      case '\\':
        out.append(std::string_view("\\\\"));
        break;
      case '\n':
        out.append(std::string_view("\\n"));
        break;
      case '\r':
        out.append(std::string_view("\\r"));
        break;
      case '\t':
        out.append(std::string_view("\\t"));
        break;
      default:
        if (c < 0x20)
          fmt::format_to(std::back_inserter(out), "\\u{:04x}", c);
        else
          out.push_back(static_cast<char>(c));
      }
      ++i;
      continue;
    }
    const std::size_t n = utf8_length(s, i);
    if (n == 0) {
      out.append(std::string_view("\\ufffd"));
      ++i;
    } else {
      out.append(s.substr(i, n));
      i += n;
    }
  }
  out.push_back('"');
}

// ---------------------------------------------------------------- model /
// frame queries

NodeFields node_fields(const NodeResults& r, NodeId n) {
  NodeFields f;
  if (n >= 0 && static_cast<std::size_t>(n) < r.dof_mask.size()) {
    const DofMask m = r.dof_mask[n];
    f.displacement =
        (m & (dof_bit(DofType::U1) | dof_bit(DofType::U2) | dof_bit(DofType::U3))) != 0;
    f.rotation = (m & (dof_bit(DofType::UR1) | dof_bit(DofType::UR2) | dof_bit(DofType::UR3))) != 0;
    f.temperature = (m & kTemperatureBits) != 0;
    f.nt = f.temperature || (static_cast<std::size_t>(n) < r.nt_field.size() && r.nt_field[n] != 0);
    return f;
  }
  f.displacement = r.any_displacement;
  f.rotation = r.any_rotation;
  f.temperature = r.any_temperature && r.nt_field.empty();
  f.nt = r.any_temperature;
  return f;
}

int n_translations(ModelSpace space) {
  return space == ModelSpace::ThreeD ? 3 : 2;
}

void average_block(const OutputBlock& block, std::vector<double>& out) {
  const std::size_t nc = block.names.size();
  out.assign(nc, 0.0);
  if (nc == 0 || block.n_points <= 0) return;
  const std::size_t np = std::min<std::size_t>(block.n_points, block.values.size() / nc);
  if (np == 0) return;
  for (std::size_t p = 0; p < np; ++p)
    for (std::size_t c = 0; c < nc; ++c) out[c] += block.values[p * nc + c];
  for (auto& v : out) v /= static_cast<double>(np);
}

void average_section_point(const OutputBlock& block, int k, std::vector<double>& out) {
  const std::size_t nc = block.names.size();
  out.assign(nc, 0.0);
  const int ns = std::max(block.section_points, 1);
  if (nc == 0 || block.n_points <= 0 || k < 0 || k >= ns) return;
  const auto np = static_cast<int>(std::min<std::size_t>(block.n_points, block.values.size() / nc));
  const int nip = np / ns;
  if (nip == 0) return;
  for (int p = 0; p < nip; ++p)
    for (std::size_t c = 0; c < nc; ++c)
      out[c] += block.values[static_cast<std::size_t>(p * ns + k) * nc + c];
  for (auto& v : out) v /= static_cast<double>(nip);
}

int voigt_slot(std::string_view name) {
  if (name.size() != 3 || (name[0] != 'S' && name[0] != 'E')) return -1;
  const std::string_view ij = name.substr(1);
  if (ij == "11") return 0;
  if (ij == "22") return 1;
  if (ij == "33") return 2;
  if (ij == "12") return 3;
  if (ij == "13") return 4;
  if (ij == "23") return 5;
  return -1;
}

namespace {
std::string upper(std::string_view s) {
  std::string u(s);
  for (auto& c : u) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return u;
}
} // namespace

std::vector<NodeId> request_nodes_by_label(const Model& model, const std::string& nset,
                                           const std::vector<NodeId>& nodes) {
  std::vector<NodeId> out;
  if (!nodes.empty()) {
    out = nodes;
  } else if (!nset.empty()) {
    if (auto it = model.nsets.find(upper(nset)); it != model.nsets.end()) out = it->second;
  } else {
    out.resize(model.mesh.n_nodes());
    std::iota(out.begin(), out.end(), NodeId{0});
  }
  const auto& labels = model.mesh.node_labels;
  std::sort(out.begin(), out.end(), [&](NodeId a, NodeId b) { return labels[a] < labels[b]; });
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<ElemId> request_elements_by_type(const Model& model, const std::string& elset,
                                             const std::vector<ElemId>& elements) {
  std::vector<ElemId> out;
  if (!elements.empty()) {
    out = elements;
  } else if (!elset.empty()) {
    if (auto it = model.elsets.find(upper(elset)); it != model.elsets.end()) out = it->second;
  } else {
    out.resize(model.mesh.n_elements());
    std::iota(out.begin(), out.end(), ElemId{0});
  }
  const auto& types = model.mesh.elem_types;
  const auto& labels = model.mesh.elem_labels;
  std::sort(out.begin(), out.end(), [&](ElemId a, ElemId b) {
    if (types[a] != types[b]) return types[a] < types[b];
    if (model.mesh.variant(a) != model.mesh.variant(b))
      return model.mesh.variant(a) < model.mesh.variant(b);
    return labels[a] < labels[b];
  });
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

double step_fraction(const Model& model, int step_index, double step_time) {
  if (step_index < 0 || step_index >= static_cast<int>(model.steps.size())) return 0.0;
  const double period = model.steps[step_index].inc.period;
  return period > 0.0 ? step_time / period : 1.0;
}

} // namespace gapfem::output
