/// @file Module.cc
/// The extension module hexex._core: error translation, version and the extraction itself.
/// The public Python API (argument checks, result classes) is in python/hexex/.

#include "ArrayConversions.hh"
#include "Bindings.hh"

#include <HexEx/Core/Error.hh>
#include <HexEx/HexEx.hh>
#include <HexEx/IO/ReportJson.hh>
#include <HexEx/Mesh/HexMeshQuality.hh>

#include <nanobind/stl/optional.h>
#include <nanobind/stl/string.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace HexExPython {

namespace {

using Clock = std::chrono::steady_clock;

/// Seconds since @p t0.
double secondsSince(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

/// The provenance as a dict of int32 numpy arrays sharing one owner: hex_source_tet (h,),
/// hex_grid_cell (h, 3), vertex_source_tet (k,), vertex_grid_coords (k, 3).
nb::dict provenanceToArrays(HexEx::HexProvenance&& prov) {
    auto* owned = new HexEx::HexProvenance(std::move(prov));
    nb::capsule owner(owned, [](void* p) noexcept { delete static_cast<HexEx::HexProvenance*>(p); });
    static std::int32_t none[3] = {0, 0, 0};  // empty vectors may have no buffer
    const auto flat = [](auto& v) -> std::int32_t* { return v.empty() ? none : reinterpret_cast<std::int32_t*>(v.data()); };
    nb::dict d;
    d["hex_source_tet"] = nb::cast(NumpyInts(flat(owned->hex_source_tet), {owned->hex_source_tet.size()}, owner));
    d["hex_grid_cell"] = nb::cast(NumpyInts(flat(owned->hex_grid_cell), {owned->hex_grid_cell.size(), 3}, owner));
    d["vertex_source_tet"] = nb::cast(NumpyInts(flat(owned->vertex_source_tet), {owned->vertex_source_tet.size()}, owner));
    d["vertex_grid_coords"] =
        nb::cast(NumpyInts(flat(owned->vertex_grid_coords), {owned->vertex_grid_coords.size(), 3}, owner));
    return d;
}

/// Extracts the hex mesh of the map given as arrays; returns (points, hexes, polyhedra,
/// report JSON, provenance dict or None). The GIL is released from the conversion to the
/// end of the extraction.
nb::tuple extract(const DoubleArray& points, const nb::handle& tets, const DoubleArray& params, int threads,
                  double epsilon, bool merge, const std::optional<Int32Array>& rotations, std::uint64_t max_memory,
                  bool cheap_folds, bool annihilation_retries, bool provenance) {
    if (threads < 0) throw std::invalid_argument("threads must be >= 0 (0 = all hardware threads), got " + std::to_string(threads));
    if (!(epsilon >= 0 && epsilon < 0.5)) throw std::invalid_argument("epsilon must be in [0, 0.5), got " + HexEx::jsonNumber(epsilon));
    const TetIndices tetIdx = tetIndices(tets);
    std::vector<int> given;
    if (rotations) {
        requireArrayShape("rotations", *rotations, {static_cast<long>(tetIdx.n_tets), 4});
        given.assign(rotations->data(), rotations->data() + 4 * tetIdx.n_tets);
    }
    HexEx::HexMesh hm;
    HexEx::HexProvenance prov;
    std::string json;
    {
        nb::gil_scoped_release release;
        const auto t_start = Clock::now();
        HexEx::ReportExtras extras;
        HexEx::ExtractionReport rep;
        {
            // The converted mesh lives only in this scope; freeing it counts in the total.
            HexEx::ParametrizedTetMesh pm = toTetMesh(points, tetIdx, params);
            extras.read_s = secondsSince(t_start);
            HexEx::ExtractionOptions opt;
            opt.threads = threads;
            opt.epsilon = epsilon;
            opt.merge = merge;
            opt.max_memory = max_memory;
            opt.cheap_folds = cheap_folds;
            opt.annihilation_retries = annihilation_retries;
            if (rotations) opt.given_rotations = &given;
            if (provenance) opt.provenance = &prov;
            rep = HexEx::extractHexMesh(std::move(pm), hm, opt);  // takes the parameters over, no copy
        }
        extras.quality = HexEx::computeQuality(hm, threads);
        extras.total_s = secondsSince(t_start);
        json = HexEx::reportToJson(rep, extras);
    }
    nb::tuple mesh = hexMeshToArrays(std::move(hm));
    nb::object provArrays = provenance ? nb::object(provenanceToArrays(std::move(prov))) : nb::none();
    return nb::make_tuple(mesh[0], mesh[1], mesh[2], json, provArrays);
}

} // namespace

} // namespace HexExPython

NB_MODULE(_core, m) {
    namespace nb = nanobind;
    m.doc() = "C++ core of the hexex package (use the functions of the hexex package, not these).";
    // Bad input from the library becomes ValueError carrying its message (file, line, reason);
    // an exceeded memory budget (ResourceError, a kind of InputError) becomes MemoryError.
    nb::register_exception_translator([](const std::exception_ptr& p, void*) {
        try {
            std::rethrow_exception(p);
        } catch (const HexEx::ResourceError& e) {
            PyErr_SetString(PyExc_MemoryError, e.what());
        } catch (const HexEx::InputError& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        }
    });
    m.def("version", &HexEx::version, "Library version string (x.y.z).");
    m.def("extract", &HexExPython::extract, nb::arg("points"), nb::arg("tets"), nb::arg("params"), nb::arg("threads"),
          nb::arg("epsilon"), nb::arg("merge"), nb::arg("rotations").none(), nb::arg("max_memory"), nb::arg("cheap_folds"),
          nb::arg("annihilation_retries"), nb::arg("provenance"),
          "Extracts the hex mesh of checked arrays; returns (points, hexes, polyhedra, report_json, provenance or None).");
    HexExPython::bindMapFunctions(m);
    HexExPython::bindHexMeshFunctions(m);
    HexExPython::bindUntangleFunctions(m);
    HexExPython::bindOptimizeFunctions(m);
}
