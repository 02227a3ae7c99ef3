#pragma once
/// @file FileBytes.hh
/// @ingroup io
/// The bytes of an input file as one read-only view: memory-mapped where POSIX mmap is
/// available and the file is a non-empty regular file (no copy into a string, no zeroing
/// of a buffer the size of the file), read into memory otherwise (pipes, empty files,
/// other systems).

#include <cstddef>
#include <string>
#include <string_view>

namespace HexEx {
namespace detail {

/// A whole input file, mapped or read; movable, not copyable. The view stays valid as long
/// as the object lives.
class FileBytes {
public:
    /// Opens @p path; InputError "<path>: cannot open file: <reason>" (also for a
    /// directory: "is a directory") or "<path>: read error".
    explicit FileBytes(const std::string& path);
    /// Unmaps the file.
    ~FileBytes();
    /// Takes over the bytes of @p other, which becomes empty.
    FileBytes(FileBytes&& other) noexcept;
    /// Releases this object's bytes and takes over those of @p other.
    FileBytes& operator=(FileBytes&& other) noexcept;
    FileBytes(const FileBytes&) = delete;
    FileBytes& operator=(const FileBytes&) = delete;

    /// The file's bytes.
    std::string_view view() const {
        return mapped_ ? std::string_view(static_cast<const char*>(mapped_), size_) : std::string_view(text_);
    }
    /// True if the bytes are memory-mapped (false: read into memory).
    bool mapped() const { return mapped_ != nullptr; }

private:
    /// Unmaps the file (if mapped) and forgets it.
    void release() noexcept;

    void* mapped_ = nullptr;  ///< start of the mapping, or null
    std::size_t size_ = 0;    ///< length of the mapping
    std::string text_;        ///< the bytes when not mapped
};

} // namespace detail
} // namespace HexEx
