#include "linalg/blas_workspace.hpp"

#include "linalg/blas.hpp"

#include <fmt/format.h>
#include <fstream>
#include <sys/resource.h>

namespace gapfem {
namespace {

/// VmSize of this process, bytes (0 when unknown).
unsigned long long address_space_used() {
  std::ifstream in("/proc/self/status");
  std::string key;
  unsigned long long kb = 0;
  while (in >> key) {
    if (key == "VmSize:" && in >> kb) return kb * 1024;
    in.ignore(1 << 20, '\n');
  }
  return 0;
}

} // namespace

std::optional<std::string> reserve_blas_workspace() {
  rlimit as{};
  if (getrlimit(RLIMIT_AS, &as) != 0 || as.rlim_cur == RLIM_INFINITY) return std::nullopt;
  const unsigned long long limit = as.rlim_cur, used = address_space_used();
  // the buffer, the thread's stack and the first arrays of a small model
  const unsigned long long need = kBlasBufferBytes + (16ull << 20);
  if (used + need > limit) {
    constexpr double MiB = 1024.0 * 1024.0;
    return fmt::format(
        "out of memory before the analysis: the address-space limit (ulimit -v {} KiB) leaves "
        "{:.0f} MiB after gapfem has loaded, and its linear algebra (OpenBLAS) maps a {:.0f} MiB "
        "work buffer; raise the limit to at least {:.0f} MiB (ulimit -v {}) plus what the model "
        "needs",
        limit / 1024, limit > used ? (limit - used) / MiB : 0.0, kBlasBufferBytes / MiB,
        (used + need) / MiB, (used + need) / 1024);
  }
  // a 1 x 1 product maps the buffer now, while the room is there
  const int one = 1;
  const double a = 1.0, b = 1.0, alpha = 1.0, beta = 0.0;
  double c = 0.0;
  dgemm_("N", "N", &one, &one, &one, &alpha, &a, &one, &b, &one, &beta, &c, &one);
  return std::nullopt;
}

} // namespace gapfem
