#pragma once
/// @file blas_workspace.hpp
/// OpenBLAS (Debian's BLAS) maps a 128 MiB work buffer per thread at its first call and, when the
/// address space has no room for it, retries the mapping forever (0.3.21, memory.c): under an
/// address-space limit (ulimit -v) a run would hang in its first factorisation. Before anything
/// is read, the program checks the room the limit leaves and makes the BLAS take its buffer at
/// once (docs/robustness.md, "Memory limits").
#include <optional>
#include <string>

namespace gapfem {

/// The address space OpenBLAS maps for its work buffer (BUFFER_SIZE of x86_64: 32 << 22 bytes;
/// seen as mmap(len=0x8000000) in the hung runs).
inline constexpr unsigned long long kBlasBufferBytes = 128ull << 20;

/// Without an address-space limit: nothing. With one: when the room left is below the BLAS
/// buffer and a margin, the sentence to stop with; otherwise a tiny BLAS call maps the buffer now
/// (the later calls reuse it) and nullopt.
std::optional<std::string> reserve_blas_workspace();

} // namespace gapfem
