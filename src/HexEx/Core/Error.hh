#pragma once
/// @file Error.hh
/// @ingroup kernel
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

/// The input would need more memory than the budget allows (ExtractionOptions::max_memory),
/// or an allocation failed. The message names the cause (e.g. the tets with the largest
/// parametric images) and what to do. A kind of InputError, so that callers that report
/// bad input report this too.
class ResourceError : public InputError {
public:
    /// An error with a complete message.
    explicit ResourceError(const std::string& what) : InputError(what) {}
};

} // namespace HexEx
