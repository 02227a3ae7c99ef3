/// @file HexExFileParallelTest.cc
/// Tests of the .hexex reader's parallel path for large tet sections (20,000 tets or
/// more): the same mesh as written, any token layout, and for every kind of defect the same
/// file:line:reason message the sequential parser gives.

#include <HexEx/Core/Error.hh>
#include <HexEx/Generators/Generators.hh>
#include <HexEx/IO/HexExFile.hh>

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace HexEx;

namespace {

/// A cube of 6 * 15^3 = 20,250 tets: large enough for the parallel path.
const ParametrizedTetMesh& largeMesh() {
    static const ParametrizedTetMesh pm = generateCube(15, 3);
    return pm;
}

/// The mesh's file split into lines (without line breaks).
std::vector<std::string> largeLines() {
    std::ostringstream os;
    writeHexExStream(os, largeMesh());
    std::vector<std::string> lines;
    std::istringstream is(os.str());
    for (std::string l; std::getline(is, l);) lines.push_back(l);
    return lines;
}

std::string join(const std::vector<std::string>& lines, const char* sep = "\n") {
    std::string s;
    for (const auto& l : lines) s += l + sep;
    return s;
}

/// Index in largeLines() of the line of tet @p c (line numbers are this + 1).
std::size_t tetLineIndex(std::size_t c) { return largeMesh().mesh.n_vertices() + 2 + c; }

/// Tokens of one line.
std::vector<std::string> tokens(const std::string& line) {
    std::istringstream is(line);
    std::vector<std::string> t;
    for (std::string s; is >> s;) t.push_back(s);
    return t;
}

std::string joinTokens(const std::vector<std::string>& t) {
    std::string s;
    for (std::size_t i = 0; i < t.size(); ++i) s += (i ? " " : "") + t[i];
    return s;
}

std::string errorOf(const std::string& text, int threads = 0) {
    try {
        readHexExBuffer(text, "big.hexex", nullptr, threads);
    } catch (const InputError& e) {
        return e.what();
    }
    ADD_FAILURE() << "no InputError";
    return "";
}

void expectError(const std::string& text, std::size_t line, const std::string& reason, int threads = 0) {
    const std::string msg = errorOf(text, threads);
    const std::string prefix = "big.hexex:" + std::to_string(line) + ": ";
    EXPECT_EQ(msg.rfind(prefix, 0), 0u) << "message: " << msg << "\nexpected prefix: " << prefix;
    EXPECT_NE(msg.find(reason), std::string::npos) << "message: " << msg << "\nexpected reason: " << reason;
}

void expectSameMesh(const ParametrizedTetMesh& a, const ParametrizedTetMesh& b) {
    ASSERT_EQ(a.mesh.n_cells(), b.mesh.n_cells());
    ASSERT_EQ(a.mesh.n_vertices(), b.mesh.n_vertices());
    for (std::size_t c = 0; c < a.mesh.n_cells(); ++c) {
        ASSERT_EQ(a.mesh.cell_vertices(CellHandle(static_cast<int>(c))), b.mesh.cell_vertices(CellHandle(static_cast<int>(c))))
            << "tet " << c;
        for (int i = 0; i < 4; ++i)
            for (int k = 0; k < 3; ++k) ASSERT_EQ(a.params[c][i][k], b.params[c][i][k]) << "tet " << c;
    }
}

} // namespace

TEST(HexExFileParallel, ReadsWhatWasWritten) {
    const auto lines = largeLines();
    ASSERT_GE(largeMesh().mesh.n_cells(), 20000u);
    const auto pm = readHexExBuffer(join(lines), "big.hexex");
    expectSameMesh(largeMesh(), pm);
    EXPECT_TRUE(pm.mesh.has_adjacency());
    // On one thread (chunked parse too) and token by token: the same mesh.
    expectSameMesh(largeMesh(), readHexExBuffer(join(lines), "big.hexex", nullptr, 1));
    expectSameMesh(largeMesh(), detail::readHexExBufferTokenByToken(join(lines), "big.hexex", nullptr, 1));
}

TEST(HexExFileParallel, AnyLayout) {
    // Every tet over three lines, CRLF line ends and tabs: the same mesh.
    auto lines = largeLines();
    std::vector<std::string> out(lines.begin(), lines.begin() + static_cast<long>(tetLineIndex(0)));
    for (std::size_t c = 0; c < largeMesh().mesh.n_cells(); ++c) {
        const auto t = tokens(lines[tetLineIndex(c)]);
        out.push_back(t[0] + "\t" + t[1] + " " + t[2] + " " + t[3]);
        out.push_back(joinTokens(std::vector<std::string>(t.begin() + 4, t.begin() + 10)));
        out.push_back("  " + joinTokens(std::vector<std::string>(t.begin() + 10, t.end())) + "\t");
    }
    expectSameMesh(largeMesh(), readHexExBuffer(join(out, "\r\n"), "big.hexex"));
    // Line numbers follow the layout: a bad token in the third line of tet 15000.
    const std::size_t third = tetLineIndex(0) + 3 * 15000 + 2;
    out[third] = "  x" + out[third].substr(2);
    expectError(join(out, "\r\n"), third + 1, "expected a number for parameter");
}

TEST(HexExFileParallel, MalformedNumberNamesTetAndLine) {
    auto lines = largeLines();
    auto t = tokens(lines[tetLineIndex(12345)]);
    t[8] = "0.5abc";  // parameter v of corner 1 (tokens: 4 indices, then u v w per corner)
    lines[tetLineIndex(12345)] = joinTokens(t);
    expectError(join(lines), tetLineIndex(12345) + 1,
                "expected a number for parameter v of corner 1 of tet 12345, got '0.5abc'");
}

TEST(HexExFileParallel, NaNIsRefused) {
    auto lines = largeLines();
    auto t = tokens(lines[tetLineIndex(20000)]);
    t[15] = "nan";
    lines[tetLineIndex(20000)] = joinTokens(t);
    expectError(join(lines), tetLineIndex(20000) + 1, "NaN or infinite value 'nan' for parameter w of corner 3 of tet 20000");
}

TEST(HexExFileParallel, VertexIndexOutOfRange) {
    auto lines = largeLines();
    auto t = tokens(lines[tetLineIndex(15000)]);
    const std::string nv = std::to_string(largeMesh().mesh.n_vertices());
    t[2] = nv;
    lines[tetLineIndex(15000)] = joinTokens(t);
    expectError(join(lines), tetLineIndex(15000) + 1, "vertex index " + nv + " of tet 15000 out of range [0, " + nv + ")");
}

TEST(HexExFileParallel, RepeatedVertex) {
    auto lines = largeLines();
    auto t = tokens(lines[tetLineIndex(17000)]);
    t[3] = t[1];
    lines[tetLineIndex(17000)] = joinTokens(t);
    expectError(join(lines), tetLineIndex(17000) + 1, "tet 17000 repeats vertex " + t[1]);
}

TEST(HexExFileParallel, TruncatedAndTrailingData) {
    auto lines = largeLines();
    const std::size_t last = tetLineIndex(largeMesh().mesh.n_cells() - 1);
    auto t = tokens(lines[last]);
    t.pop_back();
    auto cut = lines;
    cut[last] = joinTokens(t);
    expectError(join(cut), last + 1, "unexpected end of file: expected parameter w of corner 3 of tet 20249 (file declares 20250 tets)");
    auto extra = lines;
    extra.push_back("7");
    expectError(join(extra), last + 2, "unexpected data after last tet");
}

TEST(HexExFileParallel, InvertedTetListedWithItsLine) {
    // Swapping two corners (with their parameters) inverts one tet in 3D.
    auto lines = largeLines();
    auto t = tokens(lines[tetLineIndex(9999)]);
    std::swap(t[0], t[1]);
    for (int k = 0; k < 3; ++k) std::swap(t[static_cast<std::size_t>(4 + k)], t[static_cast<std::size_t>(7 + k)]);
    lines[tetLineIndex(9999)] = joinTokens(t);
    expectError(join(lines), tetLineIndex(9999) + 1,
                "1 of 20250 tets are inverted in 3D (negatively oriented): tet 9999 (line " +
                    std::to_string(tetLineIndex(9999) + 1) + ")");
}

/// Outcome of reading @p text on @p threads threads (with @p tokenByToken, without the
/// chunked parse): the error message, or a digest of the mesh.
std::string outcomeOf(const std::string& text, int threads, bool tokenByToken = false) {
    try {
        const auto pm = tokenByToken ? detail::readHexExBufferTokenByToken(text, "big.hexex", nullptr, threads)
                                     : readHexExBuffer(text, "big.hexex", nullptr, threads);
        std::ostringstream os;
        os.precision(17);
        os << "ok " << pm.mesh.n_vertices() << " " << pm.mesh.n_cells();
        for (std::size_t c = 0; c < pm.mesh.n_cells(); ++c) {
            for (auto v : pm.mesh.cell_vertices(CellHandle(static_cast<int>(c)))) os << " " << v.idx();
            for (const auto& p : pm.params[c]) os << " " << p[0] << " " << p[1] << " " << p[2];
        }
        return os.str();
    } catch (const InputError& e) {
        return e.what();
    }
}

TEST(HexExFileParallel, MutatedFilesReadAsSequentially) {
    // Random byte edits in the tet section: the chunked parse, on 1 and 2 threads, must give
    // exactly what the token-by-token parser gives (the same mesh, or the same file:line:reason).
    const auto lines = largeLines();
    const std::string base = join(lines);
    std::size_t tetStart = 0;
    for (std::size_t i = 0; i < tetLineIndex(0); ++i) tetStart += lines[i].size() + 1;
    const std::string alphabet = " \n\t0123456789.-+eEx";
    std::mt19937 rng(11);
    int accepted = 0;
    for (int it = 0; it < 30; ++it) {
        std::string t = base;
        const int edits = 1 + static_cast<int>(rng() % 3);
        for (int m = 0; m < edits; ++m) {
            const std::size_t pos = tetStart + rng() % (t.size() - tetStart);
            const char ch = alphabet[rng() % alphabet.size()];
            switch (rng() % 3) {
            case 0: t[pos] = ch; break;
            case 1: t.erase(pos, 1); break;
            default: t.insert(pos, 1, ch); break;
            }
        }
        const std::string seq = outcomeOf(t, 1, true);
        for (const int threads : {1, 2}) {
            const std::string par = outcomeOf(t, threads);
            EXPECT_EQ(seq.substr(0, 300), par.substr(0, 300)) << "iteration " << it << ", " << threads << " threads";
            EXPECT_EQ(seq, par) << "iteration " << it << ", " << threads << " threads";
        }
        if (seq.rfind("ok", 0) == 0) ++accepted;
    }
    EXPECT_LT(accepted, 30);  // most edits are caught
}

TEST(HexExFileParallel, RepeatedVertexInTetCutByAChunkBoundary) {
    // Indices padded to 40 characters so that most chunk cuts (8 chunks on 2 threads, at
    // (n - begin) * i / 8, moved to the next space) fall among a tet's indices; the tet so
    // cut gets a repeated vertex of the same width (the file keeps its length, so the cuts
    // stay where they are) and must be reported as in the sequential parser.
    auto lines = largeLines();
    const auto pad = [](const std::string& s) { return std::string(40 - s.size(), '0') + s; };
    for (std::size_t c = 0; c < largeMesh().mesh.n_cells(); ++c) {
        auto t = tokens(lines[tetLineIndex(c)]);
        for (int i = 0; i < 4; ++i) t[static_cast<std::size_t>(i)] = pad(t[static_cast<std::size_t>(i)]);
        lines[tetLineIndex(c)] = joinTokens(t);
    }
    const std::string text = join(lines);
    expectSameMesh(largeMesh(), readHexExBuffer(text, "big.hexex", nullptr, 2));
    std::size_t begin = 0;  // end of the tet count token
    for (std::size_t l = 0; l < tetLineIndex(0); ++l) begin += lines[l].size() + 1;
    --begin;
    const std::size_t n = text.size();
    int cutTets = 0;
    std::size_t prev = begin;
    for (std::size_t i = 1; i < 8; ++i) {
        std::size_t p = std::max(begin + (n - begin) * i / 8, prev);
        while (p < n && text[p] != ' ' && text[p] != '\n') ++p;
        prev = p;
        std::istringstream before(text.substr(begin, p - begin));
        std::size_t count = 0;
        for (std::string s; before >> s;) ++count;
        if (count % 16 == 0 || count % 16 >= 4) continue;  // the cut is not among the indices
        ++cutTets;
        const std::size_t c = count / 16;
        auto mutated = lines;
        auto t = tokens(mutated[tetLineIndex(c)]);
        t[3] = t[0];
        mutated[tetLineIndex(c)] = joinTokens(t);
        const std::string idx = std::to_string(std::stoll(t[0]));
        expectError(join(mutated), tetLineIndex(c) + 1, "tet " + std::to_string(c) + " repeats vertex " + idx, 2);
    }
    EXPECT_GT(cutTets, 0) << "no chunk cut fell among a tet's indices";
}

TEST(HexExFileParallel, ControlBytesAsSequentially) {
    // \v, \f and \r separate tokens like spaces; other bytes below ' ' (counted by the
    // parallel pass's exact fallback) are part of a token, which then is malformed.
    auto lines = largeLines();
    for (const std::size_t c : {100u, 9000u, 19000u}) {
        auto t = tokens(lines[tetLineIndex(c)]);
        lines[tetLineIndex(c)] = t[0] + "\v" + t[1] + "\f" + t[2] + "\r " + joinTokens(std::vector<std::string>(t.begin() + 3, t.end()));
    }
    const std::string spaced = join(lines);
    expectSameMesh(largeMesh(), readHexExBuffer(spaced, "big.hexex", nullptr, 2));
    for (const char bad : {'\x01', '\x1f', '\x08', '\x0e'}) {
        auto mutated = lines;
        auto t = tokens(mutated[tetLineIndex(15000)]);
        t[5] = t[5] + std::string(1, bad);
        mutated[tetLineIndex(15000)] = joinTokens(t);
        const std::string text = join(mutated);
        EXPECT_EQ(outcomeOf(text, 1, true), outcomeOf(text, 1)) << "byte " << int(bad);
        EXPECT_EQ(outcomeOf(text, 1, true), outcomeOf(text, 2)) << "byte " << int(bad);
        expectError(text, tetLineIndex(15000) + 1, "expected a number for parameter v of corner 0 of tet 15000", 2);
    }
}

TEST(HexExFileParallel, MutatedVertexSectionReadAsSequentially) {
    // Random byte edits in the vertex section (read by parseVerticesFast() unless something
    // is unusual): the same positions, mesh and line numbers as the token-by-token parser, or
    // the same file:line:reason. The cube's 4,096 vertices are small enough for any edit to be
    // in reach; edits that keep the file valid move positions, which the digest shows.
    const auto lines = largeLines();
    const std::string base = join(lines);
    const std::size_t vertexStart = lines[0].size() + 1;
    std::size_t vertexEnd = vertexStart;
    for (std::size_t i = 1; i <= largeMesh().mesh.n_vertices(); ++i) vertexEnd += lines[i].size() + 1;
    auto digest = [](const std::string& text, bool tokenByToken) -> std::string {
        try {
            const auto pm = tokenByToken ? detail::readHexExBufferTokenByToken(text, "big.hexex", nullptr, 1)
                                         : readHexExBuffer(text, "big.hexex", nullptr, 2);
            std::ostringstream os;
            os.precision(17);
            os << "ok " << pm.mesh.n_vertices() << " " << pm.mesh.n_cells();
            for (std::size_t v = 0; v < pm.mesh.n_vertices(); ++v) {
                const Vec3d& p = pm.mesh.position(VertexHandle(static_cast<int>(v)));
                os << " " << p[0] << " " << p[1] << " " << p[2];
            }
            for (std::size_t c = 0; c < pm.mesh.n_cells(); ++c)
                for (auto v : pm.mesh.cell_vertices(CellHandle(static_cast<int>(c)))) os << " " << v.idx();
            return os.str();
        } catch (const InputError& e) {
            return e.what();
        }
    };
    const std::string alphabet = " \n\t\v\x01" "0123456789.-+eEx";
    std::mt19937 rng(23);
    int accepted = 0, failed = 0;
    for (int it = 0; it < 40; ++it) {
        std::string t = base;
        const int edits = 1 + static_cast<int>(rng() % 2);
        for (int m = 0; m < edits; ++m) {
            const std::size_t pos = vertexStart + rng() % (vertexEnd - vertexStart);
            const char ch = alphabet[rng() % alphabet.size()];
            switch (rng() % 3) {
            case 0: t[pos] = ch; break;
            case 1: t.erase(pos, 1); break;
            default: t.insert(pos, 1, ch); break;
            }
        }
        const std::string seq = digest(t, true), fast = digest(t, false);
        EXPECT_EQ(seq.substr(0, 300), fast.substr(0, 300)) << "iteration " << it;
        EXPECT_EQ(seq, fast) << "iteration " << it;
        (seq.rfind("ok", 0) == 0 ? accepted : failed) += 1;
    }
    EXPECT_GT(failed, 0);  // some edits make the file invalid, so the fallback ran
    EXPECT_GT(accepted, 0);
    // The unchanged file: the positions as written.
    const ParametrizedTetMesh pm = readHexExBuffer(base, "big.hexex", nullptr, 2);
    for (std::size_t v = 0; v < pm.mesh.n_vertices(); ++v)
        ASSERT_EQ(pm.mesh.position(VertexHandle(static_cast<int>(v))), largeMesh().mesh.position(VertexHandle(static_cast<int>(v))));
}
