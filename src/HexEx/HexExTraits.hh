#pragma once
/// @file HexExTraits.hh
/// @ingroup kernel
/// The one-call API for any mesh kernel: extractHexMesh() templated over the input and
/// output mesh types, read and written through TetMeshTraits and HexMeshOutputTraits
/// (see MeshTraits.hh and Documentation/traits.md). Including this header also brings the
/// built-in kernel's overload (HexEx.hh) and the plain-array adapters (ArrayMeshTraits.hh).

#include "HexEx.hh"
#include "Mesh/ArrayMeshTraits.hh"
#include "Mesh/MeshTraits.hh"

#include <type_traits>
#include <utility>

namespace HexEx {

namespace detail {

/// True if the templated extractHexMesh() handles (@p InMesh, @p OutMesh): both have
/// traits and the pair is not exactly the built-in kernel, which the non-template
/// overload in HexEx.hh handles. Types without traits (e.g. a class derived from
/// ParametrizedTetMesh) fall back to the non-template overload by conversion.
template <class InMesh, class OutMesh>
inline constexpr bool useTraitsOverload =
    hasTetMeshTraits<InMesh> && hasHexMeshOutputTraits<OutMesh> &&
    !(std::is_same_v<InMesh, ParametrizedTetMesh> && std::is_same_v<OutMesh, HexMesh>);

} // namespace detail

/// Extracts the hex mesh of @p input, any mesh with TetMeshTraits, into @p output, any
/// mesh with HexMeshOutputTraits.
///
/// The input is copied into the built-in kernel (toParametrizedTetMesh(), which builds the
/// adjacency; a ParametrizedTetMesh whose adjacency is already built is used in place), the
/// extraction runs as in the non-template overload (taking the copy's parameters over as its
/// working copy), and the result is written through the
/// output traits (fromHexMesh(); a HexMesh output is written directly). @p output is
/// cleared first and is left untouched if an exception is thrown before the writing starts.
///
/// This overload takes part only when both types have traits and they are not exactly
/// (ParametrizedTetMesh, HexMesh), so calls on the built-in kernel keep resolving to the
/// non-template overload. Throws InputError for unusable input (out-of-range vertex index,
/// repeated vertex, non-manifold faces, non-finite parameters); defective maps never throw.
template <class InMesh, class OutMesh,
          std::enable_if_t<detail::useTraitsOverload<InMesh, OutMesh>, int> = 0>
ExtractionReport extractHexMesh(const InMesh& input, OutMesh& output, const ExtractionOptions& options = {}) {
    // pm: the input in place (const) or its copy, whose parameters the pipeline takes over.
    auto run = [&](auto&& pm) {
        if constexpr (std::is_same_v<OutMesh, HexMesh>) {
            return extractHexMesh(std::forward<decltype(pm)>(pm), output, options);
        } else {
            HexMesh hm;
            ExtractionReport report = extractHexMesh(std::forward<decltype(pm)>(pm), hm, options);
            fromHexMesh(hm, output);
            return report;
        }
    };
    if constexpr (std::is_same_v<InMesh, ParametrizedTetMesh>) {
        if (input.mesh.has_adjacency()) return run(input);
    }
    return run(toParametrizedTetMesh(input));
}

} // namespace HexEx
