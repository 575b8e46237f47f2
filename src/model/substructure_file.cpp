#include "model/substructure_file.hpp"

#include "common/archive.hpp"
#include "common/error.hpp"
#include "common/safe_file.hpp"

#include <cerrno>
#include <cstring>
#include <fmt/format.h>

namespace gapfem {
namespace {

constexpr std::string_view kMagic = "GAPFEM-SUBSTRUCTURE\n";
/// 2: the reduced mass (a flag, then the matrix) follows the stiffness; files of version 1 (no
/// mass) are still read
constexpr std::uint32_t kVersion = 2;

void lists(ArchiveWriter& a, const std::vector<std::vector<int>>& v) {
  a.pod(static_cast<std::uint64_t>(v.size()));
  for (const auto& l : v) a.vec(l);
}

void lists(ArchiveReader& a, std::vector<std::vector<int>>& v) {
  v.resize(static_cast<std::size_t>(a.get<std::uint64_t>()));
  for (auto& l : v) a.vec(l);
}

} // namespace

void write_substructure_file(const std::filesystem::path& file, const SubstructureLibrary& lib) {
  ArchiveWriter a;
  const SubstructureType& t = lib.type;
  a.str(t.name);
  a.str(lib.deck);
  a.str(lib.job);
  a.pod(lib.fingerprint);
  a.vec(t.node_labels);
  a.vec(t.coords);
  lists(a, t.node_dofs);
  a.pod(t.size);
  a.vec(t.stiffness);
  a.pod(static_cast<std::uint8_t>(t.mass.empty() ? 0 : 1));
  if (!t.mass.empty()) a.vec(t.mass);
  a.pod(static_cast<std::uint8_t>(lib.has_recovery ? 1 : 0));
  if (lib.has_recovery) {
    const SubstructureRecovery& r = lib.recovery;
    a.vec(r.internal_node);
    a.vec(r.internal_dof);
    a.vec(r.ii_ptr);
    a.vec(r.ii_col);
    a.vec(r.ii_val);
    a.vec(r.ir_ptr);
    a.vec(r.ir_col);
    a.vec(r.ir_val);
  }
  const std::string body = a.take();
  ArchiveWriter head;
  head.bytes(kMagic.data(), kMagic.size());
  head.pod(kVersion);
  head.pod(fnv1a(body));
  // written aside and renamed: a run killed while writing leaves the old library (if any) intact;
  // never through a link or into a pipe (common/safe_file.hpp)
  std::string bytes = head.take();
  bytes += body;
  bool written = false;
  try {
    written = files::write_replace(file, bytes);
  } catch (const Error& e) {
    throw SubstructureFileError(e.what());
  }
  if (!written)
    throw SubstructureFileError(
        fmt::format("cannot write '{}': {}", file.string(), std::strerror(errno)));
}

SubstructureLibrary read_substructure_file(const std::filesystem::path& file, bool recovery) {
  std::string data;
  bool read = false;
  try {
    read = files::read_all(file, data); // a regular file only: a pipe would never end
  } catch (const Error& e) {
    throw SubstructureFileError(e.what());
  }
  if (!read)
    throw SubstructureFileError(
        fmt::format("cannot read '{}': {}", file.string(), std::strerror(errno)));
  if (data.compare(0, kMagic.size(), kMagic) != 0)
    throw SubstructureFileError(
        fmt::format("'{}' is not a gapfem substructure file (gapfem cannot read Abaqus's .sim or "
                    ".sup substructure libraries; generate the substructure with gapfem)",
                    file.string()));
  SubstructureLibrary lib;
  try {
    ArchiveReader head(std::string_view(data).substr(kMagic.size()));
    const auto version = head.get<std::uint32_t>();
    if (version != kVersion && version != 1)
      throw SubstructureFileError(fmt::format("'{}' was written by another version of gapfem; "
                                              "generate the substructure again",
                                              file.string()));
    const auto sum = head.get<std::uint64_t>();
    const std::string_view body =
        std::string_view(data).substr(kMagic.size() + sizeof(std::uint32_t) + sizeof(sum));
    if (fnv1a(body) != sum)
      throw SubstructureFileError(fmt::format("'{}' is damaged (its checksum does not match); "
                                              "generate the substructure again",
                                              file.string()));
    ArchiveReader a(body);
    SubstructureType& t = lib.type;
    a.str(t.name);
    a.str(lib.deck);
    a.str(lib.job);
    a.pod(lib.fingerprint);
    a.vec(t.node_labels);
    a.vec(t.coords);
    lists(a, t.node_dofs);
    a.pod(t.size);
    a.vec(t.stiffness);
    if (version >= 2 && a.get<std::uint8_t>() != 0) a.vec(t.mass);
    t.file = file.string();
    const auto n = static_cast<std::size_t>(t.n_dofs());
    if (t.coords.size() != t.node_labels.size() || t.node_dofs.size() != t.node_labels.size() ||
        t.stiffness.size() != n * n || (!t.mass.empty() && t.mass.size() != n * n))
      throw SubstructureFileError(fmt::format("'{}' is inconsistent", file.string()));
    lib.has_recovery = a.get<std::uint8_t>() != 0;
    if (recovery && lib.has_recovery) {
      SubstructureRecovery& r = lib.recovery;
      a.vec(r.internal_node);
      a.vec(r.internal_dof);
      a.vec(r.ii_ptr);
      a.vec(r.ii_col);
      a.vec(r.ii_val);
      a.vec(r.ir_ptr);
      a.vec(r.ir_col);
      a.vec(r.ir_val);
    }
  } catch (const RestartDataError&) {
    throw SubstructureFileError(
        fmt::format("'{}' ends early (damaged); generate the substructure again", file.string()));
  }
  return lib;
}

} // namespace gapfem
