#pragma once
/// @file Parallel.hh
/// @ingroup kernel
/// A minimal deterministic parallel loop: the range is cut into contiguous chunks, one
/// per thread, so per-chunk results can be concatenated in chunk order.

#include <algorithm>
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

} // namespace HexEx
