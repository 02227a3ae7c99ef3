#pragma once
/// @file BlockOutput.hh
/// @ingroup io
/// Output assembled in a memory block and handed to a stream in large pieces, with number
/// formatting by DecimalFormat.hh (no iostream formatting per number), and a helper that
/// formats the items of a long range on several threads in the same byte order while the
/// calling thread hands the finished pieces to the stream.

#include "../Core/Parallel.hh"
#include "DecimalFormat.hh"

#include <algorithm>
#include <atomic>
#include <charconv>
#include <condition_variable>
#include <cstdint>
#include <cstring>
#include <exception>
#include <memory>
#include <mutex>
#include <ostream>
#include <string>
#include <string_view>
#include <thread>
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
    /// Appends the line "n v_0 ... v_(n-1)\n" of the n integers in [@p b, @p e) (the same bytes as
    /// appending them one by one; a line of up to 20 numbers is written without a check per number).
    BlockOutput& intLine(const int* b, const int* e) {
        const std::size_t n = static_cast<std::size_t>(e - b);
        if (n > 20) {  // 12 characters a number: more than kSlack may hold
            *this << n;
            for (; b != e; ++b) *this << ' ' << *b;
            return *this << '\n';
        }
        char* at = formatUnsigned(&buf_[used_], static_cast<std::uint32_t>(n));
        for (; b != e; ++b) {
            *at++ = ' ';
            at = putInt(at, *b);
        }
        *at++ = '\n';
        used_ = static_cast<std::size_t>(at - buf_.data());
        flushIfFull();
        return *this;
    }
    /// Appends the line "a b\n" (the same bytes as appending a, ' ', b and '\n').
    BlockOutput& intPair(int a, int b) {
        char* at = putInt(&buf_[used_], a);
        *at++ = ' ';
        at = putInt(at, b);
        *at++ = '\n';
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

    /// Writes @p v in decimal at @p at (at most 11 characters); @return one past the last.
    HEXEX_FORMAT_INLINE static char* putInt(char* at, int v) {
        return v >= 0 ? formatUnsigned(at, static_cast<std::uint32_t>(v)) : std::to_chars(at, at + 12, v).ptr;
    }
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
/// items are formatted in pieces on that many threads while the calling thread appends the
/// finished pieces in order (so handing the bytes to the sink overlaps the formatting of
/// the next pieces); the bytes do not depend on the thread count. At most 2 @p threads
/// pieces are held at once. An exception of @p format or of the sink stops the workers and
/// is rethrown.
template <class Format>
void formatItems(BlockOutput& out, std::size_t n, int threads, Format&& format) {
    // Small pieces (a few hundred kB of text) keep the buffers' memory low; fewer items than
    // kParallel are formatted on the calling thread.
    constexpr std::size_t kPiece = std::size_t(1) << 13, kParallel = std::size_t(1) << 16;
    if (threads <= 1 || n < kParallel) {
        for (std::size_t i = 0; i < n; ++i) format(out, i);
        return;
    }
    const std::size_t pieces = (n + kPiece - 1) / kPiece;
    const std::size_t slots = 2 * static_cast<std::size_t>(threads);  // piece p goes to buffer p % slots
    std::vector<std::unique_ptr<BlockOutput>> buffers;
    for (std::size_t s = 0; s < slots; ++s) buffers.push_back(std::make_unique<BlockOutput>(nullptr, kPiece * 64));
    std::vector<std::size_t> done(slots, SIZE_MAX);  // the finished piece each buffer holds
    std::mutex mutex;
    std::condition_variable finished, freed;
    std::size_t appended = 0;  // pieces appended to out so far
    bool stop = false;
    std::exception_ptr error;
    std::atomic<std::size_t> next{0};
    const auto work = [&] {
        for (;;) {
            const std::size_t p = next.fetch_add(1);
            if (p >= pieces) return;
            BlockOutput& local = *buffers[p % slots];
            {
                std::unique_lock<std::mutex> lock(mutex);
                freed.wait(lock, [&] { return stop || p < appended + slots; });  // piece p - slots appended
                if (stop) return;
            }
            try {
                local.clear();
                for (std::size_t i = p * kPiece, e = std::min(n, i + kPiece); i < e; ++i) format(local, i);
            } catch (...) {
                const std::lock_guard<std::mutex> lock(mutex);
                if (!error) error = std::current_exception();
                stop = true;
                finished.notify_all();
                freed.notify_all();
                return;
            }
            const std::lock_guard<std::mutex> lock(mutex);
            done[p % slots] = p;
            finished.notify_all();
        }
    };
    std::vector<std::thread> workers;
    for (int t = 0; t < threads; ++t) workers.emplace_back(work);
    try {
        for (std::size_t p = 0; p < pieces; ++p) {
            {
                std::unique_lock<std::mutex> lock(mutex);
                finished.wait(lock, [&] { return stop || done[p % slots] == p; });
                if (stop) break;
            }
            out << buffers[p % slots]->pending();
            const std::lock_guard<std::mutex> lock(mutex);
            appended = p + 1;
            freed.notify_all();
        }
    } catch (...) {
        const std::lock_guard<std::mutex> lock(mutex);
        if (!error) error = std::current_exception();
        stop = true;
        freed.notify_all();
    }
    for (auto& w : workers) w.join();
    if (error) std::rethrow_exception(error);
}

} // namespace detail
} // namespace HexEx
