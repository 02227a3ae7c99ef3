#pragma once
/// @file Memory.hh
/// @ingroup kernel
/// Memory sizes: what the machine has available now, parsing and printing byte counts.

#include <cstdint>
#include <string>

namespace HexEx {

/// Bytes this process can allocate now without pushing others out: MemAvailable of
/// /proc/meminfo (Linux), lowered to the free part of a cgroup v2 limit
/// (/sys/fs/cgroup/memory.max minus memory.current, not counting the cgroup's reclaimable
/// page cache) if there is one; otherwise the free
/// physical memory from sysconf(); 0 if none of these is known.
std::uint64_t availableMemoryBytes();

/// The default memory budget of an extraction: half of availableMemoryBytes() (a safe
/// fraction on a shared machine), at least 64 MiB; 0 (no limit) if nothing is known.
std::uint64_t defaultMemoryBudget();

/// Parses a size such as "2G", "500M", "1.5g", "800K", "4096" or "2GiB" (K, M, G, T are
/// powers of 1024; an optional trailing "B" or "iB" is accepted). Throws InputError
/// naming the text for anything else, for zero or negative sizes and for sizes beyond
/// 2^62 bytes.
std::uint64_t parseByteSize(const std::string& text);

/// A byte count for messages: "512 B", "3.2 MB", "1.50 GB" (powers of 1024).
std::string formatBytes(double bytes);

} // namespace HexEx
