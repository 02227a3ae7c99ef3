/// @file VtkDataBlocks.cc
/// Base64 and zlib data blocks of VTK XML files.

#include "VtkDataBlocks.hh"

#include <zlib.h>

#include <array>
#include <cctype>
#include <vector>

namespace HexEx {
namespace detail {

namespace {

constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

int sextet(char c) {
    static const std::array<signed char, 256> kTable = [] {
        std::array<signed char, 256> t{};
        t.fill(-1);
        for (int i = 0; i < 64; ++i) t[static_cast<unsigned char>(kAlphabet[i])] = static_cast<signed char>(i);
        return t;
    }();
    return kTable[static_cast<unsigned char>(c)];
}

std::uint64_t readUint(const std::string& b, std::size_t at, int bytes, bool bigEndian) {
    std::uint64_t v = 0;
    for (int i = 0; i < bytes; ++i)
        v = (v << 8) | static_cast<unsigned char>(b[at + static_cast<std::size_t>(bigEndian ? i : bytes - 1 - i)]);
    return v;
}

void putUint(std::string& o, std::uint64_t v) {
    for (int k = 0; k < 8; ++k) o += static_cast<char>((v >> (8 * k)) & 0xff);
}

} // namespace

std::string BlockSource::take(std::uint64_t n) {
    if (n > bytesLeft()) throw BlockError("needs " + std::to_string(n) + " bytes, at most " + std::to_string(bytesLeft()) + " left");
    if (!base64_) {
        const std::string out(data_.substr(pos_, static_cast<std::size_t>(n)));
        pos_ += static_cast<std::size_t>(n);
        return out;
    }
    while (pending_.size() < n) {
        char q[4];
        int got = 0;
        for (; got < 4 && pos_ < data_.size(); ++pos_)
            if (!std::isspace(static_cast<unsigned char>(data_[pos_]))) q[got++] = data_[pos_];
        if (got == 0) throw BlockError("base64 data ends after " + std::to_string(pos_) + " characters, " +
                                       std::to_string(n - pending_.size()) + " more bytes needed");
        if (got < 4) throw BlockError("base64 data ends inside a 4-character group at character " + std::to_string(pos_));
        int v[4], pad = 0;
        for (int i = 0; i < 4; ++i) {
            v[i] = q[i] == '=' && i >= 2 ? 0 : sextet(q[i]);
            if (q[i] == '=' && i >= 2) ++pad;
            else if (pad || v[i] < 0)
                throw BlockError("invalid base64 character '" + std::string(1, q[i]) + "' before character " +
                                 std::to_string(pos_));
        }
        const unsigned bits = static_cast<unsigned>(v[0] << 18 | v[1] << 12 | v[2] << 6 | v[3]);
        for (int i = 0; i < 3 - pad; ++i) pending_ += static_cast<char>((bits >> (16 - 8 * i)) & 0xff);
    }
    std::string out = pending_.substr(0, static_cast<std::size_t>(n));
    pending_.erase(0, static_cast<std::size_t>(n));
    return out;
}

std::string readVtkBlock(BlockSource& src, int hb, bool compressed, bool be) {
    if (!compressed) {
        const std::uint64_t n = readUint(src.take(static_cast<std::uint64_t>(hb)), 0, hb, be);
        return src.take(n);
    }
    const std::string head = src.take(3 * static_cast<std::uint64_t>(hb));
    const std::uint64_t blocks = readUint(head, 0, hb, be), blockSize = readUint(head, static_cast<std::size_t>(hb), hb, be),
                        lastSize = readUint(head, 2 * static_cast<std::size_t>(hb), hb, be);
    if (blocks > src.bytesLeft() / static_cast<std::uint64_t>(hb))
        throw BlockError("compressed header declares " + std::to_string(blocks) + " blocks, more than the data can hold");
    const std::string sizes = src.take(blocks * static_cast<std::uint64_t>(hb));
    std::string out;
    for (std::uint64_t b = 0; b < blocks; ++b) {
        const std::uint64_t csize = readUint(sizes, static_cast<std::size_t>(b * hb), hb, be);
        const std::uint64_t usize = (b + 1 == blocks && lastSize != 0) ? lastSize : blockSize;
        const std::string in = src.take(csize);
        if (usize > 1032 * csize + 64)  // beyond zlib's maximum compression ratio
            throw BlockError("compressed block " + std::to_string(b) + " claims " + std::to_string(usize) +
                             " bytes from " + std::to_string(csize));
        const std::size_t at = out.size();
        out.resize(at + static_cast<std::size_t>(usize));
        uLongf len = static_cast<uLongf>(usize);
        const int rc = uncompress(reinterpret_cast<Bytef*>(&out[at]), &len, reinterpret_cast<const Bytef*>(in.data()),
                                  static_cast<uLong>(in.size()));
        if (rc != Z_OK || len != usize)
            throw BlockError("corrupt zlib data in compressed block " + std::to_string(b) + " (" +
                             (rc == Z_OK ? "inflates to " + std::to_string(len) + " of " + std::to_string(usize) + " bytes"
                                         : std::string(zError(rc))) +
                             ")");
    }
    return out;
}

std::string makeVtkBlock(std::string_view data, bool compress) {
    std::string o;
    if (!compress) {
        putUint(o, data.size());
        o += data;
        return o;
    }
    constexpr std::size_t kBlock = 1 << 15;
    const std::size_t blocks = (data.size() + kBlock - 1) / kBlock;
    std::vector<std::string> parts(blocks);
    for (std::size_t b = 0; b < blocks; ++b) {
        const std::string_view in = data.substr(b * kBlock, kBlock);
        uLongf len = compressBound(static_cast<uLong>(in.size()));
        parts[b].resize(len);
        compress2(reinterpret_cast<Bytef*>(&parts[b][0]), &len, reinterpret_cast<const Bytef*>(in.data()),
                  static_cast<uLong>(in.size()), Z_BEST_SPEED);
        parts[b].resize(len);
    }
    putUint(o, blocks);
    putUint(o, kBlock);
    putUint(o, data.size() % kBlock);
    for (const auto& p : parts) putUint(o, p.size());
    for (const auto& p : parts) o += p;
    return o;
}

std::string base64Encode(std::string_view in) {
    std::string out;
    out.reserve((in.size() + 2) / 3 * 4);
    for (std::size_t i = 0; i < in.size(); i += 3) {
        const std::size_t n = std::min<std::size_t>(3, in.size() - i);
        unsigned bits = 0;
        for (std::size_t k = 0; k < 3; ++k) bits = bits << 8 | (k < n ? static_cast<unsigned char>(in[i + k]) : 0u);
        for (std::size_t k = 0; k < 4; ++k) out += k <= n ? kAlphabet[(bits >> (18 - 6 * k)) & 63] : '=';
    }
    return out;
}

} // namespace detail
} // namespace HexEx
