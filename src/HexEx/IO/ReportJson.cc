/// @file ReportJson.cc
/// JSON rendering of the extraction report.

#include "ReportJson.hh"

#include "../Core/Version.hh"
#include "OptimizeReportJson.hh"

#include <charconv>
#include <cmath>
#include <sstream>

namespace HexEx {

std::string jsonQuote(const std::string& s) {
    std::string out = "\"";
    for (const char ch : s) {
        const unsigned char u = static_cast<unsigned char>(ch);
        switch (ch) {
        case '"': out += "\\\""; break;
        case '\\': out += "\\\\"; break;
        case '\n': out += "\\n"; break;
        case '\r': out += "\\r"; break;
        case '\t': out += "\\t"; break;
        case '\b': out += "\\b"; break;
        case '\f': out += "\\f"; break;
        default:
            if (u < 0x20 || u == 0x7f) {
                static const char* hex = "0123456789abcdef";
                out += "\\u00";
                out += hex[u >> 4];
                out += hex[u & 15];
            } else {
                out += ch;
            }
        }
    }
    return out + "\"";
}

std::string jsonNumber(double x) {
    if (!std::isfinite(x)) return "null";
    if (x == 0) return "0";  // also for -0
    char buf[64];
    const auto res = std::to_chars(buf, buf + sizeof buf, x);
    return std::string(buf, res.ptr);
}

namespace {

/// Writes `"key": value` entries of one object with commas and indentation.
class ObjectWriter {
public:
    ObjectWriter(std::ostringstream& out, int indent) : out_(out), indent_(indent) { out_ << "{"; }
    void raw(const char* key, const std::string& value) {
        out_ << (first_ ? "\n" : ",\n") << std::string(static_cast<std::size_t>(indent_ + 2), ' ')
             << jsonQuote(key) << ": " << value;
        first_ = false;
    }
    void num(const char* key, long v) { raw(key, std::to_string(v)); }
    void num(const char* key, double v) { raw(key, jsonNumber(v)); }
    void boolean(const char* key, bool v) { raw(key, v ? "true" : "false"); }
    void close() { out_ << (first_ ? "}" : "\n" + std::string(static_cast<std::size_t>(indent_), ' ') + "}"); }

private:
    std::ostringstream& out_;
    int indent_;
    bool first_ = true;
};

/// Renders a nested object with @p fill called on its writer.
template <class Fill>
std::string object(int indent, Fill&& fill) {
    std::ostringstream s;
    ObjectWriter w(s, indent);
    fill(w);
    w.close();
    return s.str();
}

} // namespace

std::string reportToJson(const ExtractionReport& r, const ReportExtras& x) {
    const auto& in = r.input;
    const auto& out = r.output;
    const auto& d = r.darts;
    const auto& t = r.timings_s;
    const auto& v = r.validation;
    std::string doc = object(0, [&](ObjectWriter& top) {
        top.raw("input", object(2, [&](ObjectWriter& w) {
            w.num("vertices", in.vertices);
            w.num("tets", in.tets);
            w.num("boundary_faces", in.boundary_faces);
            w.num("flipped_tets", in.flipped_tets);
            w.num("degenerate_tets", in.degenerate_tets);
            w.num("singular_edges", in.singular_edges);
            w.num("parametric_volume", in.parametric_volume);
            w.num("singular_vertices", in.singular_vertices);
            w.num("ambiguous_transitions", in.ambiguous_transitions);
            w.num("unresolved_transitions", in.unresolved_transitions);
            w.num("snapped_coordinates", in.snapped_coordinates);
            w.num("inconsistent_transitions", in.inconsistent_transitions);
            w.num("repaired_corners", in.repaired_corners);
            if (!in.repairs.empty()) {
                // Bounded: at most 32 entries, the first by vertex.
                auto vec = [](const Vec3d& v) {
                    return "[" + jsonNumber(v[0]) + ", " + jsonNumber(v[1]) + ", " + jsonNumber(v[2]) + "]";
                };
                std::string list = "[";
                for (std::size_t k = 0; k < in.repairs.size(); ++k) {
                    const auto& e = in.repairs[k];
                    list += std::string(k ? "," : "") + "\n      {\"tet\": " + std::to_string(e.tet) +
                            ", \"corner\": " + std::to_string(e.corner) + ", \"vertex\": " + std::to_string(e.vertex) +
                            ", \"original\": " + vec(e.original) + ", \"repaired\": " + vec(e.repaired) + "}";
                }
                list += "\n    ]";
                w.raw("repairs", list);
            }
        }));
        top.raw("output", object(2, [&](ObjectWriter& w) {
            w.num("vertices", out.vertices);
            w.num("hexes", out.hexes);
            w.num("non_hex_cells", out.non_hex_cells);
            w.num("quads", out.quads);
            w.num("boundary_quads", out.boundary_quads);
            w.num("unconnected_darts", out.unconnected_darts);
            w.num("relinked_faces", out.relinked_faces);
        }));
        top.raw("darts", object(2, [&](ObjectWriter& w) {
            w.num("extracted", d.extracted);
            w.num("anti", d.anti);
            w.num("annihilated_pairs", d.annihilated_pairs);
            w.num("remaining_anti", d.remaining_anti);
            w.num("asymmetric_links", d.asymmetric_links);
            w.num("cancelled_fold_points", d.cancelled_fold_points);
            w.num("annihilation_order", static_cast<long>(d.annihilation_order));
            w.num("broken_cells_after_annihilation", d.broken_cells_after_annihilation);
            if (d.reconnected_cells > 0 || d.unreconnected_cells > 0) {  // only where cells were reconnected or left broken
                w.num("reconnected_cells", d.reconnected_cells);
                w.num("unreconnected_cells", d.unreconnected_cells);
            }
            if (!d.unreconnected.empty()) {  // the groups left, each named by its smallest dart (at most 8)
                std::string list = "[";
                for (std::size_t k = 0; k < d.unreconnected.size(); ++k) {
                    const auto& u = d.unreconnected[k];
                    list += std::string(k ? "," : "") + "\n      {\"dart\": " + std::to_string(u.dart) + ", \"tet\": " + std::to_string(u.tet) +
                            ", \"darts\": " + std::to_string(u.darts) + ", \"broken_cells\": " + std::to_string(u.broken_cells) +
                            ", \"reason\": " + jsonQuote(u.reason) + "}";
                }
                w.raw("unreconnected", list + "\n    ]");
            }
        }));
        if (r.arcs.edges > 0 || r.arcs.faces > 0) {
            // Only with ExtractionOptions::arcs (hexex extract --edge-arcs / --face-patches).
            auto list = [](const std::vector<int>& ids) {
                std::string s = "[";
                for (std::size_t k = 0; k < ids.size(); ++k) s += (k ? ", " : "") + std::to_string(ids[k]);
                return s + "]";
            };
            top.raw("arcs", object(2, [&](ObjectWriter& w) {
                w.num("edges", r.arcs.edges);
                w.num("faces", r.arcs.faces);
                w.num("failed_edges", r.arcs.failed_edges);
                w.num("failed_faces", r.arcs.failed_faces);
                w.raw("failed_edge_ids", list(r.arcs.failed_edge_ids));
                w.raw("failed_face_ids", list(r.arcs.failed_face_ids));
                w.num("seconds", r.timings_s.arcs);
            }));
        }
        top.boolean("valid_all_hex", r.valid_all_hex);
        top.raw("quality", object(2, [&](ObjectWriter& w) {
            w.num("min_scaled_jacobian", x.quality.min_scaled_jacobian);
            w.num("mean_scaled_jacobian", x.quality.mean_scaled_jacobian);
            w.num("inverted_hexes", x.quality.inverted_hexes);
            w.num("invalid_hexes", x.quality.invalid_hexes);
            w.num("undecided_hexes", x.quality.undecided_hexes);
            w.boolean("certified_valid", x.quality.invalid_hexes == 0 && x.quality.undecided_hexes == 0);
        }));
        if (x.untangle) {
            const UntangleReport& u = *x.untangle;
            top.raw("untangle", object(2, [&](ObjectWriter& w) {
                w.num("hexes", u.hexes);
                w.num("inverted_before", u.inverted_before);
                w.num("inverted_after", u.inverted_after);
                w.num("invalid_before", u.invalid_before);
                w.num("invalid_after", u.invalid_after);
                w.num("undecided_before", u.undecided_before);
                w.num("undecided_after", u.undecided_after);
                w.num("min_scaled_jacobian_before", u.min_scaled_jacobian_before);
                w.num("mean_scaled_jacobian_before", u.mean_scaled_jacobian_before);
                w.num("min_scaled_jacobian_after", u.min_scaled_jacobian_after);
                w.num("mean_scaled_jacobian_after", u.mean_scaled_jacobian_after);
                w.num("free_vertices", u.free_vertices);
                w.num("moved_vertices", u.moved_vertices);
                w.num("max_displacement", u.max_displacement);
                w.num("mean_displacement", u.mean_displacement);
                w.num("released_feature_vertices", u.released_feature_vertices);
                w.num("attempts", static_cast<long>(u.attempts));
                w.num("rings", static_cast<long>(u.rings));
                w.num("outer_iterations", static_cast<long>(u.outer_iterations));
                w.num("lbfgs_iterations", static_cast<long>(u.lbfgs_iterations));
                w.num("quality_iterations", static_cast<long>(u.quality_iterations));
                w.num("seconds", u.seconds);
                w.boolean("success", u.success);
                w.boolean("budget_exhausted", u.budget_exhausted);
                w.raw("message", jsonQuote(u.message));
            }));
        }
        if (x.optimize) top.raw("optimize", optimizeReportToJson(*x.optimize, 2));
        top.raw("timings_s", object(2, [&](ObjectWriter& w) {
            w.num("read", x.read_s);
            w.num("preprocess", t.preprocess);
            w.num("vertices", t.vertices);
            w.num("darts", t.darts);
            w.num("connect", t.connect);
            w.num("postprocess", t.postprocess);
            w.num("assemble", t.assemble);
            w.num("write", x.write_s);
            w.num("total", x.total_s);
        }));
        top.num("threads", static_cast<long>(r.threads));
        top.raw("version", jsonQuote(version()));
        top.raw("validation", object(2, [&](ObjectWriter& w) {
            w.boolean("valid", v.valid());
            w.num("darts", v.darts);
            w.num("not_involution", v.not_involution);
            w.num("open_links", v.open_links);
            w.num("eq1_edge_connection", v.eq1_edge_connection);
            w.num("eq2_face_connection", v.eq2_face_connection);
            w.num("eq3_quad", v.eq3_quad);
            w.num("eq4_corner", v.eq4_corner);
            w.num("eq5_strip", v.eq5_strip);
            w.num("eq6_hex", v.eq6_hex);
            w.num("boundary_darts", v.boundary_darts);
            w.raw("summary", jsonQuote(v.summary()));
            if (!v.examples.empty()) {
                // Bounded: GMapValidation::kExamplesPerCheck darts per failing check.
                std::string list = "[";
                for (std::size_t k = 0; k < v.examples.size(); ++k) {
                    const GMapViolation& e = v.examples[k];
                    std::string face = "[";
                    for (std::size_t i = 0; i < e.face_vertices.size(); ++i)
                        face += (i ? ", " : "") + std::to_string(e.face_vertices[i]);
                    face += "]";
                    list += std::string(k ? "," : "") + "\n      {\"check\": " + jsonQuote(e.check) +
                            ", \"dart\": " + std::to_string(e.dart) + ", \"face_vertices\": " + face + "}";
                }
                list += "\n    ]";
                w.raw("violations", list);
            }
        }));
        std::string warnings = "[";
        bool first = true;
        for (const auto* list : {&r.warnings, &x.warnings})
            for (const auto& s : *list) {
                warnings += (first ? "\n    " : ",\n    ") + jsonQuote(s);
                first = false;
            }
        warnings += first ? "]" : "\n  ]";
        top.raw("warnings", warnings);
    });
    return doc + "\n";
}

} // namespace HexEx
