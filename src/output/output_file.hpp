#pragma once
/// @file output_file.hpp
/// Helpers shared by the result writers: a buffered output file written in
/// large chunks, number formatting (Abaqus E-format, JSON round-trip numbers),
/// and small queries on frames and models (which fields a node carries,
/// averaging of integration-point values).
#include "common/types.hpp"
#include "elements/element_kernel.hpp"
#include "results/results.hpp"

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fmt/compile.h>
#include <fmt/format.h>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace gapfem::output {

/// A file written through a large in-memory buffer. Text is formatted into
/// buffer() with fmt::format_to and handed to the operating system in chunks of
/// about `chunk` bytes. Errors raise AnalysisError naming the file.
///
/// Opened with Mode::Replace, the file is written under `path` + ".tmp" and close() moves it
/// over `path` after fsync, so `path` always holds either its previous complete content or the
/// new one, never a part (docs/results.md). A failed file stays failed: the first error is thrown
/// once, later writes and close() do nothing, and a Replace file's partial copy is removed.
class OutputFile {
 public:
  /// InPlace: written under its name; Replace: staged and renamed at close(); Update: an existing
  /// file cut to a given length and appended to, fsync'ed at close() (ShadowDocument).
  enum class Mode { InPlace, Replace, Update };

  OutputFile() = default;
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  /// Create (truncate) `path` for writing (Replace: its staging copy).
  void open(const std::filesystem::path& path, Mode mode = Mode::InPlace);
  /// Mode::Update: open `file` (created when missing) keeping its first `keep` bytes, to append
  /// to them; errors name `shown`, the document the file stands for.
  void open_update(const std::filesystem::path& file, std::uintmax_t keep,
                   const std::filesystem::path& shown);
  /// Restart (docs/restart.md): continue `path` after its first `keep` bytes. When `source` (the
  /// same file of the job that wrote the restart data) is another file, `path` is created with
  /// the first `keep` bytes of `source`.
  void open_resumed(const std::filesystem::path& path, const std::filesystem::path& source,
                    std::uintmax_t keep);
  /// Bytes in the file so far, the buffer included (it is written out first).
  std::uintmax_t position();
  bool is_open() const { return _file != nullptr; }
  bool failed() const { return _failed; }
  /// The errno of the failure (0 when none).
  int error_number() const { return _errno; }
  const std::filesystem::path& path() const { return _path; }

  /// The buffer to format into; call maybe_flush() now and then.
  fmt::memory_buffer& buffer() { return _buffer; }
  /// Append text.
  void write(std::string_view text) { _buffer.append(text.data(), text.data() + text.size()); }
  /// Append raw bytes, bypassing the buffer when the block is large.
  void write_bytes(const void* data, std::size_t n);
  /// Append the whole content of another (flushed) file.
  void append_file(const std::filesystem::path& source);
  /// Append bytes [from, to) of another (flushed) file.
  void append_file_range(const std::filesystem::path& source, std::uintmax_t from,
                         std::uintmax_t to);
  /// Hand the buffer to the operating system when it holds more than the chunk
  /// size.
  void maybe_flush() {
    if (_buffer.size() >= kChunk) drain();
  }
  /// Write everything buffered and flush the C stream (for files users tail
  /// -f).
  void flush();
  /// Flush and close (Replace: fsync, then move over the final name); no-op when not open.
  void close();

  static constexpr std::size_t kChunk = std::size_t{1} << 22; ///< 4 MiB

 private:
  void drain();
  /// Takes a descriptor from files:: (-1: fail with its errno) as the stream.
  void adopt(int fd, const char* mode);
  void put(const void* data, std::size_t n);
  /// append_file_range by copy_file_range; false (nothing copied) where that is not available.
  bool copy_in_kernel(const std::filesystem::path& source, std::uintmax_t from, std::uintmax_t to);
  [[noreturn]] void fail(const char* what);

  std::FILE* _file = nullptr;
  std::filesystem::path _path;    ///< the final name
  std::filesystem::path _staging; ///< the file written (Replace: _path + ".tmp"; InPlace: _path)
  Mode _mode = Mode::InPlace;
  bool _failed = false;
  int _errno = 0;
  fmt::memory_buffer _buffer;
};

/// fsync of a directory, so that a rename in it survives a power loss (best effort).
void sync_directory(const std::filesystem::path& dir);

namespace testing {
/// Fault injection for tests: after `bytes` more bytes, every result-file write fails with
/// ENOSPC (as on a full disk); a negative value removes the limit.
void limit_writes(long long bytes);
} // namespace testing

/// Abaqus-style spaced capitals: "STATIC ANALYSIS" -> "S T A T I C   A N A L Y
/// S I S".
std::string spaced(std::string_view text);

/// Append `v` in Abaqus 1P E-format, width 12 including a leading blank
/// (" 1.2346E-03").
inline void append_e12(fmt::memory_buffer& out, double v) {
  fmt::format_to(fmt::appender(out), FMT_COMPILE(" {:>11.4E}"), v);
}

/// Append a JSON number with full round-trip precision, or null when not
/// finite.
void append_json_number(fmt::memory_buffer& out, double v);
/// Append `,"energies":{"ALLKE":…,…,"ETOTAL":…}` (results.hpp, Energies).
void append_energies(fmt::memory_buffer& out, const Energies& e);
/// Append a JSON string literal (quoted, escaped; invalid UTF-8 bytes become
/// U+FFFD).
void append_json_string(fmt::memory_buffer& out, std::string_view s);
/// Append text for an XML attribute value or element content (&, <, >, " and '
/// escaped).
void append_xml_text(fmt::memory_buffer& out, std::string_view s);
/// Append `"k":` (the key is written as is: no escaping).
void append_json_key(fmt::memory_buffer& out, std::string_view k);
/// Append `,"k":v` with v a JSON number.
void append_json_field(fmt::memory_buffer& out, std::string_view k, double v);
/// Append a JSON array of numbers.
void append_json_array(fmt::memory_buffer& out, std::span<const double> values);

/// Which result fields a node carries (from NodeResults::dof_mask, or the any_*
/// flags when the mask is absent).
struct NodeFields {
  bool displacement = false;
  bool rotation = false;
  bool temperature = false; ///< temperature DOFs (NT, RFL, CFL)
  bool nt = false;          ///< a temperature: a DOF, or the predefined field of a stress analysis
};
NodeFields node_fields(const NodeResults& r, NodeId n);

/// Number of translational components in the model space: 3 in 3-D, 2
/// otherwise.
int n_translations(ModelSpace space);

/// Average of an output block over its points (component order of
/// OutputBlock::names) into `out` (resized to names.size()).
void average_block(const OutputBlock& block, std::vector<double>& out);
/// The average over the integration points of section point `k` (0-based) of a block with
/// section points (OutputBlock::section_points).
void average_section_point(const OutputBlock& block, int k, std::vector<double>& out);

/// Voigt slot (0..5 for 11 22 33 12 13 23) of a stress/strain component name
/// such as "S12" or "E33"; -1 if the name is not of that form.
int voigt_slot(std::string_view component);

/// Nodes of a print request: explicit list, else the named set, else all nodes;
/// sorted by label.
std::vector<NodeId> request_nodes_by_label(const Model& model, const std::string& nset,
                                           const std::vector<NodeId>& nodes);
/// Elements of a print request (explicit list, else set, else all), grouped by
/// element type (in ElementType order) and sorted by label inside each type.
std::vector<ElemId> request_elements_by_type(const Model& model, const std::string& elset,
                                             const std::vector<ElemId>& elements);

/// Fraction of the step completed (step_time / period, guarded for a zero
/// period).
double step_fraction(const Model& model, int step_index, double step_time);

} // namespace gapfem::output
