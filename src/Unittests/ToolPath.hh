#pragma once
// Locating the hexex binary of this build tree from the test binary (shared by the CLI tests).

#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>
#include <unistd.h>

namespace HexExTest {

/// Path of the hexex tool: $HEXEX_TOOL if set, else <build>/src/Tools/hexex/hexex next to
/// this test binary (<build>/src/Unittests/unittests); empty if not found.
inline std::string hexexBinary() {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (const char* env = std::getenv("HEXEX_TOOL"))
        if (fs::is_regular_file(env, ec)) return env;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (ec) return {};
    const fs::path tool = self.parent_path().parent_path() / "Tools" / "hexex" / "hexex";
    if (!fs::is_regular_file(tool, ec) || ::access(tool.c_str(), X_OK) != 0) return {};
    return tool.string();
}

} // namespace HexExTest
