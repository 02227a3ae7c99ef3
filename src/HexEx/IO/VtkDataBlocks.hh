#pragma once
/// @file VtkDataBlocks.hh
/// @ingroup io
/// The binary data blocks of VTK XML files: base64 (with separately padded pieces, as VTK
/// writes them), a byte-count header of UInt32 or UInt64, and zlib compression in blocks
/// (`vtkZLibDataCompressor`).

#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace HexEx {
namespace detail {

/// Malformed block data; the message is the reason only (callers add file and position).
class BlockError : public std::runtime_error {
public:
    /// An error with the reason @p what.
    explicit BlockError(const std::string& what) : std::runtime_error(what) {}
};

/// Consecutive bytes of raw or base64-encoded data.
class BlockSource {
public:
    /// Bytes of @p data, decoded from base64 if @p base64 (whitespace is skipped, and '='
    /// padding may end any 4-character group, so concatenated encodings read as one).
    BlockSource(std::string_view data, bool base64) : data_(data), base64_(base64) {}
    /// The next @p n bytes. @throws BlockError if the data ends early or is not base64.
    std::string take(std::uint64_t n);
    /// Upper bound of the bytes left (to reject impossible sizes before allocating).
    std::uint64_t bytesLeft() const { return base64_ ? (data_.size() - pos_) / 4 * 3 + pending_.size() : data_.size() - pos_; }

private:
    std::string_view data_;
    bool base64_;
    std::size_t pos_ = 0;
    std::string pending_;  // decoded bytes not yet taken
};

/// Reads one data block: a header of @p headerBytes (4 or 8) bytes giving the byte count
/// and the bytes, or, if @p compressed, the zlib block table and the inflated blocks;
/// header values are big-endian if @p bigEndian.
/// @throws BlockError for truncated, oversized or corrupt data.
std::string readVtkBlock(BlockSource& source, int headerBytes, bool compressed, bool bigEndian = false);

/// Decodes @p bytes as consecutive numbers of @p size bytes (1, 2, 4 or 8): IEEE floats if
/// @p real, else integers (two's complement if @p isSigned), big-endian if @p bigEndian.
/// @throws BlockError for a size that is not a multiple of @p size or a non-finite value.
template <class T>
std::vector<T> decodeNumbers(std::string_view bytes, int size, bool real, bool isSigned, bool bigEndian) {
    if (bytes.size() % static_cast<std::size_t>(size))
        throw BlockError(std::to_string(bytes.size()) + " bytes, not a multiple of " + std::to_string(size));
    std::vector<T> out(bytes.size() / static_cast<std::size_t>(size));
    for (std::size_t i = 0; i < out.size(); ++i) {
        std::uint64_t u = 0;
        for (int k = 0; k < size; ++k)
            u = (u << 8) | static_cast<unsigned char>(bytes[i * static_cast<std::size_t>(size) + static_cast<std::size_t>(bigEndian ? k : size - 1 - k)]);
        if (real) {
            float f = 0;
            const auto u32 = static_cast<std::uint32_t>(u);
            double x = (std::memcpy(&f, &u32, 4), f);
            if (size == 8) std::memcpy(&x, &u, 8);
            if (!std::isfinite(x)) throw BlockError("value " + std::to_string(i) + " is not finite");
            out[i] = static_cast<T>(x);
        } else {
            long long x = static_cast<long long>(u);
            if (isSigned && size < 8 && (u >> (8 * size - 1))) x -= 1LL << (8 * size);  // sign extension
            out[i] = static_cast<T>(x);
        }
    }
    return out;
}

/// @p data as one VTK block with a UInt64 header (zlib-compressed in 32 KiB blocks if
/// @p compress), raw bytes.
std::string makeVtkBlock(std::string_view data, bool compress);

/// Standard base64 (with padding) of @p bytes.
std::string base64Encode(std::string_view bytes);

} // namespace detail
} // namespace HexEx
