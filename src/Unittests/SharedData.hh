#pragma once
/// @file SharedData.hh
/// Test support: the data folder `../shared/data` next to the repository (real maps and
/// published hex meshes), read through `xz -dc`. Tests that need it skip when it is absent.

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

namespace HexExTest {

/// Path of @p relative (e.g. "S1_polycube_scale1.hexex.xz") inside ../shared/data.
inline std::string sharedDataPath(const std::string& relative) {
    return std::string(HEXEX_SOURCE_DIR) + "/../shared/data/" + relative;
}

/// The decompressed bytes of the .xz file @p path, or "" if it is missing or xz fails.
inline std::string readXzFile(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return {};
    std::unique_ptr<FILE, int (*)(FILE*)> p(popen(("xz -dc '" + path + "' 2>/dev/null").c_str(), "r"), pclose);
    if (!p) return {};
    std::string text;
    char buf[1 << 16];
    for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, p.get())) > 0;) text.append(buf, n);
    return text;
}

/// readXzFile() of sharedDataPath(@p relative).
inline std::string readSharedXz(const std::string& relative) { return readXzFile(sharedDataPath(relative)); }

} // namespace HexExTest
