#include "common/memory.hpp"

#include <algorithm>
#include <atomic>
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

/// A number in a cgroup file ("max", a v1 "unlimited" value or missing: nullopt).
std::optional<std::uint64_t> cgroup_value(const std::string& file) {
  std::ifstream in(file);
  std::string v;
  if (!(in >> v) || v == "max") return std::nullopt;
  const std::uint64_t n = std::strtoull(v.c_str(), nullptr, 10);
  if (n >= (std::uint64_t{1} << 62)) return std::nullopt; // v1 writes "no limit" as ~2^63
  return n;
}

/// The memory the process's cgroups still allow: the tightest (limit - usage) of its memory
/// cgroup and each parent, cgroup v2 (memory.max, memory.current) or v1 (memory.limit_in_bytes,
/// memory.usage_in_bytes); nullopt without a limit.
std::optional<std::uint64_t> cgroup_room() {
  std::ifstream in("/proc/self/cgroup");
  std::string line;
  std::optional<std::uint64_t> room;
  auto bound = [&](const std::string& dir, const char* max_file, const char* used_file) {
    const auto max = cgroup_value(dir + "/" + max_file);
    const auto used = cgroup_value(dir + "/" + used_file);
    if (!max || !used) return;
    const std::uint64_t r = *max > *used ? *max - *used : 0;
    room = room ? std::min(*room, r) : r;
  };
  while (std::getline(in, line)) {
    // "0::/path" (v2) or "4:memory:/path" (v1)
    const std::size_t a = line.find(':'), b = line.find(':', a + 1);
    if (a == std::string::npos || b == std::string::npos) continue;
    const std::string controllers = line.substr(a + 1, b - a - 1);
    std::string path = line.substr(b + 1);
    const bool v2 = line.compare(0, a, "0") == 0 && controllers.empty();
    const bool v1 = controllers.find("memory") != std::string::npos;
    if (!v1 && !v2) continue;
    const std::string root = v2 ? "/sys/fs/cgroup" : "/sys/fs/cgroup/memory";
    for (;;) { // the cgroup and its parents up to the root of what this process can see
      if (v2)
        bound(root + path, "memory.max", "memory.current");
      else
        bound(root + path, "memory.limit_in_bytes", "memory.usage_in_bytes");
      if (path.empty() || path == "/") break;
      path = path.substr(0, path.rfind('/'));
    }
  }
  return room;
}

constexpr std::uint64_t kNoLimit = ~std::uint64_t{0};
std::atomic<std::uint64_t> g_limit{kNoLimit}; ///< set_memory_limit

} // namespace

void set_memory_limit(std::optional<std::uint64_t> bytes) {
  g_limit = bytes.value_or(kNoLimit);
}

std::uint64_t resident_memory_bytes() {
  return proc_kb("/proc/self/status", "VmRSS:").value_or(0);
}

std::optional<std::uint64_t> available_memory_bytes() {
  if (const auto limit = g_limit.load(); limit != kNoLimit) return limit; // a small machine
  std::optional<std::uint64_t> avail = proc_kb("/proc/meminfo", "MemAvailable:");
  auto bound = [&](std::uint64_t b) { avail = avail ? std::min(*avail, b) : b; };
  if (const auto room = cgroup_room()) bound(*room);
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
