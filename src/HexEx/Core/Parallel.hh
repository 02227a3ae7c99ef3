#pragma once
/// @file Parallel.hh
/// @ingroup kernel
/// Minimal deterministic parallel loops: the range is cut into contiguous chunks (one per
/// thread) or blocks (claimed by the threads as they finish), so per-chunk or per-block
/// results can be concatenated in range order.

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace HexEx {

/// Number of threads to use for @p requested (0 = hardware concurrency), at least 1.
inline int resolveThreadCount(int requested) {
    if (requested > 0) return requested;
    const unsigned hw = std::thread::hardware_concurrency();
    return hw == 0 ? 1 : static_cast<int>(hw);
}

/// Calls body(chunk, begin, end) for @p n_chunks contiguous chunks of [0, n), each on its
/// own thread (the first on the calling thread). Exceptions are rethrown after joining.
template <class Body>
void parallelChunks(std::size_t n, int n_chunks, Body&& body) {
    n_chunks = std::max(1, std::min<int>(n_chunks, static_cast<int>(std::max<std::size_t>(n, 1))));
    std::vector<std::thread> threads;
    std::vector<std::exception_ptr> errors(static_cast<std::size_t>(n_chunks));
    auto run = [&](int k) {
        const std::size_t b = n * static_cast<std::size_t>(k) / static_cast<std::size_t>(n_chunks);
        const std::size_t e = n * static_cast<std::size_t>(k + 1) / static_cast<std::size_t>(n_chunks);
        try {
            body(k, b, e);
        } catch (...) {
            errors[static_cast<std::size_t>(k)] = std::current_exception();
        }
    };
    for (int k = 1; k < n_chunks; ++k) threads.emplace_back(run, k);
    run(0);
    for (auto& t : threads) t.join();
    for (auto& e : errors)
        if (e) std::rethrow_exception(e);
}

/// Calls body(thread, block, begin, end) for the blocks [k * block_size, (k + 1) * block_size)
/// of [0, n) (the last one shorter), on @p n_threads threads (the first on the calling
/// thread) that each claim the next unclaimed block when done with one: for loops whose work
/// per item varies along the range, where equal chunks would leave one thread waiting.
/// Which thread runs a block is not fixed, so results must go per block (or be independent
/// of the order); @p thread indexes per-thread scratch. Exceptions are rethrown after
/// joining, the one of the lowest block first; a thread stops at its first exception.
template <class Body>
void parallelBlocks(std::size_t n, std::size_t block_size, int n_threads, Body&& body) {
    block_size = std::max<std::size_t>(1, block_size);
    const std::size_t nBlocks = (n + block_size - 1) / block_size;
    n_threads = std::max(1, std::min<int>(n_threads, static_cast<int>(std::max<std::size_t>(nBlocks, 1))));
    std::atomic<std::size_t> next{0};
    std::vector<std::exception_ptr> errors(nBlocks);
    auto run = [&](int t) {
        for (std::size_t k = next.fetch_add(1, std::memory_order_relaxed); k < nBlocks;
             k = next.fetch_add(1, std::memory_order_relaxed)) {
            try {
                body(t, k, k * block_size, std::min(n, (k + 1) * block_size));
            } catch (...) {
                errors[k] = std::current_exception();
                return;
            }
        }
    };
    std::vector<std::thread> threads;
    for (int t = 1; t < n_threads; ++t) threads.emplace_back(run, t);
    run(0);
    for (auto& t : threads) t.join();
    for (auto& e : errors)
        if (e) std::rethrow_exception(e);
}

} // namespace HexEx
