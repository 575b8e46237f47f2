#pragma once
/// @file memory.hpp
/// How much memory the process may still use: the machine's available memory (/proc/meminfo
/// MemAvailable), bounded by the process's cgroup limit and address-space limit, or the test
/// override GAPFEM_MEMORY_LIMIT (bytes of the whole process). Used to refuse a factorisation that
/// cannot fit before it is attempted.
#include <cstdint>
#include <optional>
#include <string>

namespace gapfem {

/// Sets (or with nullopt removes) a limit on the bytes of the whole process, standing in for a
/// small machine (tests; the application layer sets it from GAPFEM_MEMORY_LIMIT).
void set_memory_limit(std::optional<std::uint64_t> bytes);

/// Bytes the process can still allocate, or nullopt when nothing is known.
std::optional<std::uint64_t> available_memory_bytes();

/// The process's resident memory now (VmRSS), bytes.
std::uint64_t resident_memory_bytes();

/// "512.0 KiB", "3.2 MiB", "1.50 GiB".
std::string memory_size_text(double bytes);

} // namespace gapfem
