/// @file ArgParser.cc
/// Option parsing shared by the hexex subcommands.

#include "ArgParser.hh"

#include <cerrno>
#include <cmath>
#include <cctype>
#include <cstdlib>
#include <unistd.h>

namespace HexExTool {

std::string ParsedArgs::get(const std::string& name, const std::string& fallback) const {
    const auto it = values.find(name);
    return it == values.end() ? fallback : it->second;
}

long ParsedArgs::getInt(const std::string& name, long fallback, long lo, long hi) const {
    const auto it = values.find(name);
    return it == values.end() ? fallback : parseInt(it->second, lo, hi, "option " + name);
}

double ParsedArgs::getDouble(const std::string& name, double fallback, double lo, double hi) const {
    const auto it = values.find(name);
    return it == values.end() ? fallback : parseDouble(it->second, lo, hi, "option " + name);
}

ParsedArgs parseArgs(const Args& args, const std::vector<OptionSpec>& spec) {
    ParsedArgs out;
    auto find = [&](const std::string& s) -> const OptionSpec* {
        for (const auto& o : spec)
            if (o.name == s || (!o.alias.empty() && o.alias == s)) return &o;
        return nullptr;
    };
    bool options_done = false;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (options_done || a.empty() || a[0] != '-' || a == "-") {
            out.positional.push_back(a);
            continue;
        }
        if (a == "--") {
            options_done = true;
            continue;
        }
        std::string key = a, inline_value;
        bool has_inline = false;
        const std::size_t eq = a.find('=');
        if (a.rfind("--", 0) == 0 && eq != std::string::npos) {
            key = a.substr(0, eq);
            inline_value = a.substr(eq + 1);
            has_inline = true;
        }
        const OptionSpec* o = find(key);
        if (!o && (key == "-h" || key == "--help") && !has_inline) {
            out.values["--help"] = "";
            continue;
        }
        if (!o) throw UsageError("unknown option '" + key + "'");
        if (out.has(o->name)) throw UsageError("option '" + o->name + "' given more than once");
        if (!o->takes_value) {
            if (has_inline) throw UsageError("option '" + o->name + "' takes no value");
            out.values[o->name] = "";
        } else if (has_inline) {
            if (inline_value.empty()) throw UsageError("option '" + o->name + "' needs a value");
            out.values[o->name] = inline_value;
        } else {
            if (i + 1 >= args.size() || args[i + 1].rfind("--", 0) == 0)
                throw UsageError("option '" + key + "' needs a value");
            out.values[o->name] = args[++i];
        }
    }
    return out;
}

long parseInt(const std::string& text, long lo, long hi, const std::string& what) {
    errno = 0;
    char* end = nullptr;
    const long v = text.empty() ? 0 : std::strtol(text.c_str(), &end, 10);
    if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE || std::isspace(
            static_cast<unsigned char>(text[0])))
        throw UsageError(what + ": '" + text + "' is not an integer");
    if (v < lo || v > hi)
        throw UsageError(what + ": " + text + " is out of range [" + std::to_string(lo) + ", " +
                         std::to_string(hi) + "]");
    return v;
}

double parseDouble(const std::string& text, double lo, double hi, const std::string& what) {
    errno = 0;
    char* end = nullptr;
    const double v = text.empty() ? 0 : std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || std::isspace(static_cast<unsigned char>(text[0])))
        throw UsageError(what + ": '" + text + "' is not a number");
    if (!std::isfinite(v)) throw UsageError(what + ": '" + text + "' is not a finite number");
    if (v < lo || v > hi) throw UsageError(what + ": " + text + " is out of range");
    return v;
}

bool stderrIsTerminal() { return ::isatty(2) != 0; }

InputAndJson parseInputAndJson(const Args& args) {
    const ParsedArgs pa = parseArgs(args, {{"--json", false, ""}});
    InputAndJson r;
    r.help = pa.has("--help");
    if (r.help) return r;
    if (pa.positional.size() > 1) throw UsageError("more than one input file given");
    if (pa.positional.empty()) throw UsageError("no input file given");
    r.input = pa.positional[0];
    r.json = pa.has("--json");
    return r;
}

} // namespace HexExTool
