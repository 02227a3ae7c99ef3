#pragma once
/// @file BlockOutput.hh
/// @ingroup io
/// Output assembled in a memory block and handed to a stream in large pieces, with number
/// formatting by std::to_chars (no iostream formatting per number), and a helper that
/// formats the items of a long range on several threads in the same byte order.

#include "../Core/Parallel.hh"
#include "DecimalFormat.hh"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <memory>
#include <ostream>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace HexEx {
namespace detail {

/// True on little-endian hosts.
inline bool hostIsLittleEndian() {
    const std::uint16_t probe = 1;
    unsigned char first = 0;
    std::memcpy(&first, &probe, 1);
    return first == 1;
}

/// Bytes appended to a buffer; with a sink stream the buffer is written out whenever it
/// holds a block (1 MiB by default), without one it grows and take() returns everything.
class BlockOutput {
public:
    /// Output to @p sink (may be null: keep everything in memory) in blocks of @p blockBytes.
    explicit BlockOutput(std::ostream* sink = nullptr, std::size_t blockBytes = std::size_t(1) << 20)
        : sink_(sink), initial_(std::max<std::size_t>(blockBytes, 1)), block_(initial_) {
        buf_.resize(block_ + kSlack);
    }
    BlockOutput(const BlockOutput&) = delete;
    BlockOutput& operator=(const BlockOutput&) = delete;

    /// Appends raw bytes.
    BlockOutput& operator<<(std::string_view s) {
        if (s.empty()) return *this;  // an empty view may have a null data(), which memcpy must not get
        if (s.size() > kSlack) {
            if (sink_) {
                flush();
                if (s.size() >= block_) {
                    sink_->write(s.data(), static_cast<std::streamsize>(s.size()));
                    return *this;
                }
            } else if (used_ + s.size() + kSlack > buf_.size()) {
                grow(used_ + s.size());
            }
        }
        std::memcpy(&buf_[used_], s.data(), s.size());
        used_ += s.size();
        flushIfFull();
        return *this;
    }
    /// Appends a character.
    BlockOutput& operator<<(char c) {
        buf_[used_++] = c;
        flushIfFull();
        return *this;
    }
    /// Appends an integer in decimal.
    template <class I, class = std::enable_if_t<std::is_integral_v<I> && !std::is_same_v<I, char>>>
    BlockOutput& operator<<(I v) {
        char* at = &buf_[used_];
        // formatUnsigned() for 0 to 2^32 - 1 (the same bytes, fewer divisions), to_chars otherwise.
        bool small = static_cast<std::uint64_t>(v) <= 0xffffffffu;
        if constexpr (std::is_signed_v<I>) small = small && v >= 0;
        at = small ? formatUnsigned(at, static_cast<std::uint32_t>(v)) : std::to_chars(at, at + 24, v).ptr;
        used_ = static_cast<std::size_t>(at - buf_.data());
        flushIfFull();
        return *this;
    }
    /// Appends @p x as printf's "%.17g" does (the same bytes; reads back bit-identically).
    BlockOutput& real17(double x) {
        used_ = static_cast<std::size_t>(formatReal17(&buf_[used_], x) - buf_.data());
        flushIfFull();
        return *this;
    }
    /// Appends "x y z" of the three doubles at @p p (17 significant digits each).
    BlockOutput& vec17(const double* p) { return real17(p[0]) << ' ', real17(p[1]) << ' ', real17(p[2]); }
    /// Appends the low @p bytes (1, 2, 4 or 8) bytes of @p v, little-endian.
    BlockOutput& le(std::uint64_t v, int bytes) {
        char* p = &buf_[used_];
        for (int i = 0; i < bytes; ++i) p[i] = static_cast<char>((v >> (8 * i)) & 0xff);
        used_ += static_cast<std::size_t>(bytes);
        flushIfFull();
        return *this;
    }
    /// Appends the @p n integers or doubles at @p values, each as its low @p bytes bytes
    /// little-endian (doubles: all 8 bytes); copied in one piece where that gives the same bytes.
    template <class T>
    BlockOutput& leArray(const T* values, std::size_t n, int bytes = static_cast<int>(sizeof(T))) {
        if (hostIsLittleEndian() && bytes == static_cast<int>(sizeof(T)))
            return *this << std::string_view(reinterpret_cast<const char*>(values), n * sizeof(T));
        for (std::size_t i = 0; i < n; ++i) {
            if constexpr (std::is_floating_point_v<T>) leReal(static_cast<double>(values[i]));
            else le(static_cast<std::uint64_t>(values[i]), bytes);
        }
        return *this;
    }
    /// Appends the 8 bytes of @p x, little-endian.
    BlockOutput& leReal(double x) {
        std::uint64_t bits = 0;
        std::memcpy(&bits, &x, 8);
        return le(bits, 8);
    }
    /// Writes what is buffered to the sink (no-op without one).
    void flush() {
        if (!sink_ || used_ == 0) return;
        sink_->write(buf_.data(), static_cast<std::streamsize>(used_));
        used_ = 0;
    }
    /// Everything appended (only meaningful without a sink); leaves the buffer empty.
    std::string take() {
        buf_.resize(used_);
        std::string r = std::move(buf_);
        block_ = initial_;
        buf_.assign(block_ + kSlack, '\0');
        used_ = 0;
        return r;
    }
    /// Drops the bytes buffered and not yet written (the buffer is kept for reuse).
    void clear() { used_ = 0; }
    /// The bytes buffered and not yet written to the sink.
    std::string_view pending() const { return {buf_.data(), used_}; }

private:
    /// Room every single append may use beyond the block without a check.
    static constexpr std::size_t kSlack = 256;

    /// Keeps the invariant that at least kSlack bytes are free after every append.
    void flushIfFull() {
        if (used_ < block_) return;
        if (sink_) flush();
        else grow(used_);
    }
    /// In-memory mode: a block of at least @p bytes (geometric growth).
    void grow(std::size_t bytes) {
        block_ = std::max(block_ * 2, bytes + 1);
        buf_.resize(block_ + kSlack);
    }

    std::ostream* sink_;
    std::size_t initial_;
    std::size_t block_;
    std::string buf_;
    std::size_t used_ = 0;
};

/// Appends format(o, i) for every i in [0, n) to @p out, in order; with @p threads > 1 the
/// items are formatted in pieces on that many threads and the pieces appended in order,
/// so the bytes do not depend on the thread count.
template <class Format>
void formatItems(BlockOutput& out, std::size_t n, int threads, Format&& format) {
    constexpr std::size_t kPiece = std::size_t(1) << 15;
    if (threads <= 1 || n < 2 * kPiece) {
        for (std::size_t i = 0; i < n; ++i) format(out, i);
        return;
    }
    // One buffer per thread, reused from round to round (no allocation per piece).
    std::vector<std::unique_ptr<BlockOutput>> pieces;
    for (int t = 0; t < threads; ++t) pieces.push_back(std::make_unique<BlockOutput>(nullptr, kPiece * 64));
    for (std::size_t begin = 0; begin < n; begin += kPiece * pieces.size()) {
        const std::size_t end = std::min(n, begin + kPiece * pieces.size());
        for (const auto& p : pieces) p->clear();
        parallelChunks(end - begin, threads, [&](int k, std::size_t b, std::size_t e) {
            BlockOutput& local = *pieces[static_cast<std::size_t>(k)];
            for (std::size_t i = begin + b; i < begin + e; ++i) format(local, i);
        });
        for (const auto& p : pieces) out << p->pending();
    }
}

} // namespace detail
} // namespace HexEx
