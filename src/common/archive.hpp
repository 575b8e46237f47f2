#pragma once
/// @file archive.hpp
/// A flat binary archive for restart data (docs/restart.md): trivially copyable values, strings
/// and vectors of them, written in machine byte order. The reader checks every length against
/// what is left, so a damaged or foreign record raises RestartDataError, never a crash.
#include "common/error.hpp"

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace gapfem {

/// The 64-bit FNV-1a hash (checksums of restart records and substructure files, fingerprints).
inline std::uint64_t fnv1a(std::string_view bytes, std::uint64_t h = 1469598103934665603ull) {
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

/// Restart data that cannot be used (truncated, of another version or another model).
class RestartDataError : public Error {
 public:
  using Error::Error;
};

class ArchiveWriter {
 public:
  template <typename T>
  void pod(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes(&v, sizeof v);
  }
  void str(std::string_view s) {
    pod(static_cast<std::uint64_t>(s.size()));
    bytes(s.data(), s.size());
  }
  template <typename T>
  void vec(const std::vector<T>& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    pod(static_cast<std::uint64_t>(v.size()));
    bytes(v.data(), v.size() * sizeof(T));
  }
  /// Pairs member by member (std::pair is not trivially copyable, and padding is never written).
  template <typename A, typename B>
  void vec(const std::vector<std::pair<A, B>>& v) {
    pod(static_cast<std::uint64_t>(v.size()));
    for (const auto& [a, b] : v) {
      pod(a);
      pod(b);
    }
  }
  void strings(const std::vector<std::string>& v) {
    pod(static_cast<std::uint64_t>(v.size()));
    for (const auto& s : v) str(s);
  }
  void bytes(const void* p, std::size_t n) {
    if (n) _buf.append(static_cast<const char*>(p), n);
  }
  const std::string& data() const { return _buf; }
  std::string take() { return std::move(_buf); }

 private:
  std::string _buf;
};

class ArchiveReader {
 public:
  explicit ArchiveReader(std::string_view data)
      : _p(data.data()), _end(data.data() + data.size()) {}
  template <typename T>
  void pod(T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes(&v, sizeof v);
  }
  template <typename T>
  T get() {
    T v{};
    pod(v);
    return v;
  }
  void str(std::string& s) {
    const std::size_t n = count(1);
    s.assign(_p, n);
    _p += n;
  }
  std::string str() {
    std::string s;
    str(s);
    return s;
  }
  template <typename T>
  void vec(std::vector<T>& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    const std::size_t n = count(sizeof(T));
    v.resize(n);
    bytes(v.data(), n * sizeof(T));
  }
  template <typename A, typename B>
  void vec(std::vector<std::pair<A, B>>& v) {
    const std::size_t n = count(sizeof(A) + sizeof(B));
    v.resize(n);
    for (auto& [a, b] : v) {
      pod(a);
      pod(b);
    }
  }
  void strings(std::vector<std::string>& v) {
    const std::size_t n = count(1);
    v.resize(n);
    for (auto& s : v) str(s);
  }
  void bytes(void* p, std::size_t n) {
    if (n > static_cast<std::size_t>(_end - _p))
      throw RestartDataError("the restart record ends early");
    if (n) std::memcpy(p, _p, n);
    _p += n;
  }
  /// A view of the next n bytes (consumed).
  std::string_view view(std::size_t n) {
    if (n > static_cast<std::size_t>(_end - _p))
      throw RestartDataError("the restart record ends early");
    std::string_view v(_p, n);
    _p += n;
    return v;
  }
  bool at_end() const { return _p == _end; }

 private:
  /// A length prefix, checked against the bytes left (each element at least `unit` bytes).
  std::size_t count(std::size_t unit) {
    const auto n = get<std::uint64_t>();
    if (unit > 0 && n > static_cast<std::uint64_t>(_end - _p) / unit)
      throw RestartDataError("the restart record ends early");
    return static_cast<std::size_t>(n);
  }
  const char* _p;
  const char* _end;
};

} // namespace gapfem
