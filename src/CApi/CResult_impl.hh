#pragma once
/// @file CResult_impl.hh
/// Template bodies of CResult.hh.

#include <HexEx/Core/Error.hh>

#include <cstddef>
#include <cstring>
#include <new>

namespace HexExC {

template <class Body>
hexex_status guarded(hexex_result* r, Body&& body) noexcept {
    try {
        body();
        r->status = HEXEX_OK;
        r->message.clear();
        return HEXEX_OK;
    } catch (const ArgumentError& e) {
        return fail(r, HEXEX_ERROR_INVALID_ARGUMENT, e.what());
    } catch (const HexEx::ResourceError& e) {
        return fail(r, HEXEX_ERROR_RESOURCE, e.what());
    } catch (const HexEx::InputError& e) {
        return fail(r, HEXEX_ERROR_INPUT, e.what());
    } catch (const std::invalid_argument& e) {
        return fail(r, HEXEX_ERROR_INPUT, e.what());
    } catch (const std::bad_alloc&) {
        return fail(r, HEXEX_ERROR_RESOURCE, "out of memory");
    } catch (const std::exception& e) {
        return fail(r, HEXEX_ERROR_INTERNAL, e.what());
    } catch (...) {
        return fail(r, HEXEX_ERROR_INTERNAL, "unknown exception");
    }
}

template <class Options>
Options readOptions(const Options* in, const Options& defaults) {
    Options o = defaults;
    if (!in) return o;
    if (in->size < offsetof(Options, size) + sizeof(in->size) || in->size > sizeof(Options))
        throw ArgumentError("options: size is " + std::to_string(in->size) + ", expected at most " +
                            std::to_string(sizeof(Options)) + " (initialise the options with their _init() function)");
    // Only the fields the caller's header knew: the rest keep their defaults.
    std::memcpy(static_cast<void*>(&o), static_cast<const void*>(in), in->size);
    o.size = sizeof(Options);
    return o;
}

} // namespace HexExC
