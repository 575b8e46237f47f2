#include "common/memory.hpp"

#include <algorithm>
#include <cstdlib>
#include <fmt/format.h>
#include <fstream>
#include <string>
#include <sys/resource.h>

namespace gapfem {
namespace {

/// A "Key:   123 kB" line of a /proc file, in bytes.
std::optional<std::uint64_t> proc_kb(const char* file, const char* key) {
  std::ifstream in(file);
  std::string line;
  const std::string k = key;
  while (std::getline(in, line))
    if (line.rfind(k, 0) == 0) return std::strtoull(line.c_str() + k.size(), nullptr, 10) * 1024;
  return std::nullopt;
}

/// A number in a cgroup file ("max" or missing: nullopt).
std::optional<std::uint64_t> cgroup_value(const char* file) {
  std::ifstream in(file);
  std::string v;
  if (!(in >> v) || v == "max") return std::nullopt;
  return std::strtoull(v.c_str(), nullptr, 10);
}

} // namespace

std::uint64_t resident_memory_bytes() {
  return proc_kb("/proc/self/status", "VmRSS:").value_or(0);
}

std::optional<std::uint64_t> available_memory_bytes() {
  if (const char* limit = std::getenv("GAPFEM_MEMORY_LIMIT")) // tests: a small machine
    return std::strtoull(limit, nullptr, 10);
  std::optional<std::uint64_t> avail = proc_kb("/proc/meminfo", "MemAvailable:");
  auto bound = [&](std::uint64_t b) { avail = avail ? std::min(*avail, b) : b; };
  const auto max = cgroup_value("/sys/fs/cgroup/memory.max");
  const auto current = cgroup_value("/sys/fs/cgroup/memory.current");
  if (max && current) bound(*max > *current ? *max - *current : 0);
  rlimit as{};
  if (getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY) {
    const std::uint64_t used = proc_kb("/proc/self/status", "VmSize:").value_or(0);
    bound(as.rlim_cur > used ? as.rlim_cur - used : 0);
  }
  return avail;
}

} // namespace gapfem

namespace gapfem {

std::string memory_size_text(double bytes) {
  if (bytes < 1024.0 * 1024.0) return fmt::format("{:.1f} KiB", bytes / 1024.0);
  if (bytes < 1024.0 * 1024.0 * 1024.0) return fmt::format("{:.1f} MiB", bytes / (1024.0 * 1024.0));
  return fmt::format("{:.2f} GiB", bytes / (1024.0 * 1024.0 * 1024.0));
}

} // namespace gapfem
