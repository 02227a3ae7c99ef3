#pragma once
/// @file Error.hh
/// Exceptions thrown by the library for bad input.

#include <stdexcept>
#include <string>

namespace HexEx {

/// Bad input: malformed file, inconsistent mesh, out-of-range index. The message names
/// file, line (when known) and reason.
class InputError : public std::runtime_error {
public:
    /// An error with a complete message.
    explicit InputError(const std::string& what) : std::runtime_error(what) {}
};

} // namespace HexEx
