/// @file FileBytes.cc
/// Implementation of FileBytes: mmap on POSIX systems, readWholeFile() elsewhere and for
/// files that cannot be mapped.

#include "FileBytes.hh"
#include "ReaderSupport.hh"  // readWholeFile() where mmap is not available

#include "../Core/Error.hh"

#include <cerrno>
#include <cstring>
#include <utility>

#if defined(__unix__) || defined(__APPLE__)
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#define HEXEX_HAVE_MMAP 1
#endif

namespace HexEx {
namespace detail {

FileBytes::FileBytes(const std::string& path) {
#ifdef HEXEX_HAVE_MMAP
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) throw InputError(path + ": cannot open file: " + std::strerror(errno));
    struct stat st {};
    const bool statOk = ::fstat(fd, &st) == 0;
    const bool regular = statOk && S_ISREG(st.st_mode);
    if (statOk && S_ISDIR(st.st_mode)) {
        ::close(fd);
        throw InputError(path + ": cannot open file: is a directory");
    }
    if (regular && st.st_size > 0) {
        const auto size = static_cast<std::size_t>(st.st_size);
        // MAP_POPULATE maps the whole file in one call instead of one page fault per page.
        int flags = MAP_PRIVATE;
#ifdef MAP_POPULATE
        flags |= MAP_POPULATE;
#endif
        void* p = ::mmap(nullptr, size, PROT_READ, flags, fd, 0);
        if (p != MAP_FAILED) {
            ::close(fd);
            mapped_ = p;
            size_ = size;
            return;
        }
    }
    // Pipes, empty files, mmap refused: read from the descriptor already open (opening a
    // pipe a second time would wait for a writer that has already gone).
    char buf[1 << 16];
    for (;;) {
        const ssize_t n = ::read(fd, buf, sizeof buf);
        if (n > 0) {
            text_.append(buf, static_cast<std::size_t>(n));
        } else if (n == 0) {
            break;
        } else if (errno != EINTR) {
            ::close(fd);
            throw InputError(path + ": read error");
        }
    }
    ::close(fd);
#else
    text_ = readWholeFile(path);
#endif
}

FileBytes::~FileBytes() { release(); }

FileBytes::FileBytes(FileBytes&& other) noexcept
    : mapped_(std::exchange(other.mapped_, nullptr)), size_(std::exchange(other.size_, 0)), text_(std::move(other.text_)) {}

FileBytes& FileBytes::operator=(FileBytes&& other) noexcept {
    if (this != &other) {
        release();
        mapped_ = std::exchange(other.mapped_, nullptr);
        size_ = std::exchange(other.size_, 0);
        text_ = std::move(other.text_);
    }
    return *this;
}

void FileBytes::release() noexcept {
#ifdef HEXEX_HAVE_MMAP
    if (mapped_) ::munmap(mapped_, size_);
#endif
    mapped_ = nullptr;
    size_ = 0;
}

} // namespace detail
} // namespace HexEx
