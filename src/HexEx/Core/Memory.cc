#include "Memory.hh"

#include "Error.hh"

#include <unistd.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>

namespace HexEx {

namespace {
/// The value of a "Key:   123 kB" line of /proc/meminfo in bytes, or 0.
std::uint64_t meminfoBytes(const std::string& key) {
    std::ifstream in("/proc/meminfo");
    std::string line;
    while (std::getline(in, line))
        if (line.compare(0, key.size(), key) == 0 && line.size() > key.size() && line[key.size()] == ':')
            return static_cast<std::uint64_t>(std::strtoull(line.c_str() + key.size() + 1, nullptr, 10)) * 1024u;
    return 0;
}

/// A number from a one-line cgroup file, or 0 ("max", missing, unreadable).
std::uint64_t cgroupValue(const char* path) {
    std::ifstream in(path);
    std::string text;
    if (!(in >> text) || text.empty() || !std::isdigit(static_cast<unsigned char>(text[0]))) return 0;
    return static_cast<std::uint64_t>(std::strtoull(text.c_str(), nullptr, 10));
}

/// The page cache of the cgroup ("file" in memory.stat): counted in memory.current but
/// reclaimable, like the cache that MemAvailable counts as available. 0 if unknown.
std::uint64_t cgroupFileCache() {
    std::ifstream in("/sys/fs/cgroup/memory.stat");
    std::string key;
    std::uint64_t value = 0;
    while (in >> key >> value)
        if (key == "file") return value;
    return 0;
}
} // namespace

std::uint64_t availableMemoryBytes() {
    std::uint64_t avail = meminfoBytes("MemAvailable");
    if (avail == 0) {
        const long pages = sysconf(_SC_AVPHYS_PAGES), size = sysconf(_SC_PAGESIZE);
        if (pages > 0 && size > 0) avail = static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(size);
    }
    const std::uint64_t limit = cgroupValue("/sys/fs/cgroup/memory.max");
    if (limit > 0) {
        const std::uint64_t current = cgroupValue("/sys/fs/cgroup/memory.current"), cache = cgroupFileCache();
        const std::uint64_t used = current > cache ? current - cache : 0;
        const std::uint64_t free = limit > used ? limit - used : 0;
        if (avail == 0 || free < avail) avail = free;
    }
    return avail;
}

std::uint64_t defaultMemoryBudget() {
    const std::uint64_t avail = availableMemoryBytes();
    if (avail == 0) return 0;
    const std::uint64_t half = avail / 2, floor = 64ull << 20;
    return half < floor ? floor : half;
}

std::uint64_t parseByteSize(const std::string& text) {
    auto bad = [&](const std::string& why) { return InputError("memory size '" + text + "': " + why + " (e.g. 2G, 500M, 800K or bytes)"); };
    const char* s = text.c_str();
    char* end = nullptr;
    const double v = std::strtod(s, &end);
    if (end == s || !std::isfinite(v)) throw bad("not a number");
    std::string unit(end);
    for (char& c : unit) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    double mult = 1;
    if (!unit.empty() && std::string("KMGT").find(unit[0]) != std::string::npos) {
        mult = std::pow(1024.0, static_cast<double>(std::string("KMGT").find(unit[0]) + 1));
        unit.erase(0, 1);
    }
    if (unit != "" && unit != "B" && unit != "IB") throw bad("unknown unit");
    const double bytes = std::floor(v * mult);
    if (!(bytes >= 1)) throw bad("must be positive");
    if (bytes > std::ldexp(1.0, 62)) throw bad("too large");
    return static_cast<std::uint64_t>(bytes);
}

std::string formatBytes(double bytes) {
    const char* units[] = {"B", "KB", "MB", "GB", "TB"};
    int u = 0;
    while (bytes >= 1024 && u < 4) {
        bytes /= 1024;
        ++u;
    }
    char buf[32];
    std::snprintf(buf, sizeof buf, u == 0 ? "%.0f %s" : bytes < 10 ? "%.2f %s" : "%.1f %s", bytes, units[u]);
    return buf;
}

} // namespace HexEx
