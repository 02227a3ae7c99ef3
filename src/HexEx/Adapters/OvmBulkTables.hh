#pragma once
/// @file OvmBulkTables.hh
/// @ingroup adapters
/// Lookup tables of the bulk OpenVolumeMesh writer (OvmHexOutput): an open-addressing hash
/// table from a 128-bit key (an edge's or a face's sorted vertex indices) to a 64-bit value,
/// so that every edge and face of the output is created once without asking the mesh.
/// Internal to the OpenVolumeMesh adapter; needs no OpenVolumeMesh header.

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace HexEx {
namespace detail {

/// Open-addressing (linear probing) hash table from a key of two 64-bit words to a 64-bit
/// value. The key word `a == ~0` is reserved (marks a free slot); callers pack vertex
/// indices below 2^31, which never produce it.
class OvmKeyTable {
public:
    /// Makes room for @p n entries without rehashing.
    void reserve(std::size_t n) {
        std::size_t cap = 16;
        while (cap < 2 * n) cap *= 2;
        if (cap > slots_.size()) rehash(cap);
    }
    /// Removes all entries and frees the table.
    void clear() {
        std::vector<Slot>().swap(slots_);
        size_ = 0;
    }
    /// Number of entries.
    std::size_t size() const { return size_; }
    /// Looks up (@p a, @p b); if absent inserts it with @p value. Returns the stored value
    /// and whether it was inserted now.
    std::pair<std::uint64_t, bool> insert(std::uint64_t a, std::uint64_t b, std::uint64_t value) {
        if (2 * (size_ + 1) > slots_.size()) rehash(slots_.empty() ? 16 : 2 * slots_.size());
        const std::size_t mask = slots_.size() - 1;
        for (std::size_t i = hash(a, b) & mask;; i = (i + 1) & mask) {
            Slot& s = slots_[i];
            if (s.a == kFree) {
                s = Slot{a, b, value};
                ++size_;
                return {value, true};
            }
            if (s.a == a && s.b == b) return {s.value, false};
        }
    }

private:
    /// One slot: key words and value.
    struct Slot {
        std::uint64_t a = kFree;  ///< first key word (kFree: empty slot)
        std::uint64_t b = 0;      ///< second key word
        std::uint64_t value = 0;  ///< stored value
    };
    static constexpr std::uint64_t kFree = ~std::uint64_t(0);

    /// Mixes the key words (splitmix64 finalizer).
    static std::size_t hash(std::uint64_t a, std::uint64_t b) {
        std::uint64_t h = a * 0x9E3779B97F4A7C15ull ^ (b + 0x632BE59BD9B4E019ull);
        h = (h ^ (h >> 30)) * 0xBF58476D1CE4E5B9ull;
        h = (h ^ (h >> 27)) * 0x94D049BB133111EBull;
        return static_cast<std::size_t>(h ^ (h >> 31));
    }
    /// Moves all entries into a table of @p cap slots (a power of two).
    void rehash(std::size_t cap) {
        std::vector<Slot> old(cap);
        old.swap(slots_);
        const std::size_t mask = cap - 1;
        for (const Slot& s : old) {
            if (s.a == kFree) continue;
            std::size_t i = hash(s.a, s.b) & mask;
            while (slots_[i].a != kFree) i = (i + 1) & mask;
            slots_[i] = s;
        }
    }

    std::vector<Slot> slots_;
    std::size_t size_ = 0;
};

} // namespace detail
} // namespace HexEx
