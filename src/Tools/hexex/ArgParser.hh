#pragma once
/// @file ArgParser.hh
/// Option parsing shared by the hexex subcommands: a declared set of options (flags and
/// options with one value, long `--name`, `--name=value` or short `-o`), positional
/// arguments, and strict number parsing. Every problem throws UsageError, which the
/// subcommands turn into exit status 2.

#include "Commands.hh"

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace HexExTool {

/// Bad command line (unknown option, missing value, malformed number, ...): exit status 2.
class UsageError : public std::runtime_error {
public:
    /// An error with a complete message (without the command prefix).
    explicit UsageError(const std::string& what) : std::runtime_error(what) {}
};

/// Declaration of one option.
struct OptionSpec {
    std::string name;          ///< canonical spelling, e.g. "--output"
    bool takes_value = false;  ///< true if the option consumes the next argument
    std::string alias;         ///< optional alternative spelling, e.g. "-o"
};

/// Result of parseArgs(): positional arguments and the options given, by canonical name.
class ParsedArgs {
public:
    std::vector<std::string> positional;        ///< arguments that are not options, in order
    std::map<std::string, std::string> values;  ///< canonical name -> value ("" for flags)

    /// True if option @p name was given.
    bool has(const std::string& name) const { return values.count(name) != 0; }
    /// The value of @p name, or @p fallback if not given.
    std::string get(const std::string& name, const std::string& fallback = "") const;
    /// The value of @p name as an integer in [@p lo, @p hi], or @p fallback if not given.
    /// @throws UsageError if the value is not an integer in range.
    long getInt(const std::string& name, long fallback, long lo, long hi) const;
    /// The value of @p name as a finite double in [@p lo, @p hi], or @p fallback if not given.
    /// @throws UsageError if the value is not a finite number in range.
    double getDouble(const std::string& name, double fallback, double lo, double hi) const;
};

/// Parses @p args against @p spec. "-h"/"--help" are recognised as the flag "--help" if the
/// spec does not declare them. A lone "-" and anything not starting with '-' is
/// positional; "--" ends option parsing.
/// @throws UsageError for unknown options, missing values, values given to flags and
///         options repeated.
ParsedArgs parseArgs(const Args& args, const std::vector<OptionSpec>& spec);

/// Arguments of the commands that take one input file and an optional `--json`.
struct InputAndJson {
    std::string input;  ///< the input file
    bool json = false;  ///< --json given
    bool help = false;  ///< -h/--help given (nothing else is checked then)
};

/// Parses `IN [--json]`. @throws UsageError for unknown options, no input or several inputs.
InputAndJson parseInputAndJson(const Args& args);

/// Parses a whole string as an integer in [@p lo, @p hi]; @p what names it in the message.
/// @throws UsageError otherwise.
long parseInt(const std::string& text, long lo, long hi, const std::string& what);

/// Parses a whole string as a finite double in [@p lo, @p hi]; @p what names it in the
/// message. @throws UsageError otherwise.
double parseDouble(const std::string& text, double lo, double hi, const std::string& what);

/// True if standard error is a terminal (progress lines then update in place).
bool stderrIsTerminal();

} // namespace HexExTool
