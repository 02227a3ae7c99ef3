/// @file ReportJsonTest.cc
/// Tests of reportToJson(): a strict JSON parser checks syntax, key structure and types.

#include <HexEx/HexEx.hh>
#include <HexEx/IO/ReportJson.hh>

#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

using namespace HexEx;

namespace {

/// A parsed JSON value.
struct JValue {
    enum Kind { Null, Bool, Number, String, Array, Object } kind = Null;
    bool b = false;
    double num = 0;
    std::string str;
    std::vector<JValue> items;
    std::vector<std::pair<std::string, JValue>> members;  // in document order

    const JValue* get(const std::string& key) const {
        for (const auto& m : members)
            if (m.first == key) return &m.second;
        return nullptr;
    }
};

/// Minimal strict recursive-descent JSON parser (RFC 8259); throws std::runtime_error.
class JParser {
public:
    explicit JParser(const std::string& s) : s_(s) {}
    JValue parseDocument() {
        JValue v = value();
        ws();
        if (i_ != s_.size()) fail("trailing characters");
        return v;
    }

private:
    [[noreturn]] void fail(const std::string& why) {
        throw std::runtime_error("JSON error at offset " + std::to_string(i_) + ": " + why);
    }
    void ws() {
        while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\n' || s_[i_] == '\r' || s_[i_] == '\t')) ++i_;
    }
    bool lit(const char* w) {
        const std::string t(w);
        if (s_.compare(i_, t.size(), t) == 0) {
            i_ += t.size();
            return true;
        }
        return false;
    }
    JValue value() {
        ws();
        if (i_ >= s_.size()) fail("unexpected end");
        JValue v;
        const char c = s_[i_];
        if (c == '{') {
            v.kind = JValue::Object;
            ++i_;
            ws();
            if (i_ < s_.size() && s_[i_] == '}') {
                ++i_;
                return v;
            }
            for (;;) {
                ws();
                if (i_ >= s_.size() || s_[i_] != '"') fail("expected key");
                std::string k = string();
                for (const auto& m : v.members)
                    if (m.first == k) fail("duplicate key " + k);
                ws();
                if (i_ >= s_.size() || s_[i_++] != ':') fail("expected ':'");
                v.members.emplace_back(k, value());
                ws();
                if (i_ < s_.size() && s_[i_] == ',') { ++i_; continue; }
                if (i_ < s_.size() && s_[i_] == '}') { ++i_; return v; }
                fail("expected ',' or '}'");
            }
        }
        if (c == '[') {
            v.kind = JValue::Array;
            ++i_;
            ws();
            if (i_ < s_.size() && s_[i_] == ']') {
                ++i_;
                return v;
            }
            for (;;) {
                v.items.push_back(value());
                ws();
                if (i_ < s_.size() && s_[i_] == ',') { ++i_; continue; }
                if (i_ < s_.size() && s_[i_] == ']') { ++i_; return v; }
                fail("expected ',' or ']'");
            }
        }
        if (c == '"') {
            v.kind = JValue::String;
            v.str = string();
            return v;
        }
        if (lit("true")) { v.kind = JValue::Bool; v.b = true; return v; }
        if (lit("false")) { v.kind = JValue::Bool; return v; }
        if (lit("null")) return v;
        return number();
    }
    std::string string() {
        ++i_;  // opening quote
        std::string out;
        while (i_ < s_.size()) {
            const unsigned char c = static_cast<unsigned char>(s_[i_++]);
            if (c == '"') return out;
            if (c < 0x20) fail("raw control character in string");
            if (c != '\\') { out += static_cast<char>(c); continue; }
            if (i_ >= s_.size()) break;
            const char e = s_[i_++];
            switch (e) {
            case '"': out += '"'; break;
            case '\\': out += '\\'; break;
            case '/': out += '/'; break;
            case 'b': out += '\b'; break;
            case 'f': out += '\f'; break;
            case 'n': out += '\n'; break;
            case 'r': out += '\r'; break;
            case 't': out += '\t'; break;
            case 'u': {
                if (i_ + 4 > s_.size()) fail("short \\u escape");
                unsigned cp = 0;
                for (int k = 0; k < 4; ++k) {
                    const char h = s_[i_++];
                    if (!std::isxdigit(static_cast<unsigned char>(h))) fail("bad \\u escape");
                    cp = cp * 16 + static_cast<unsigned>(std::isdigit(static_cast<unsigned char>(h))
                                                             ? h - '0'
                                                             : std::tolower(static_cast<unsigned char>(h)) - 'a' + 10);
                }
                if (cp < 0x80) out += static_cast<char>(cp);
                else out += '?';
                break;
            }
            default: fail("bad escape");
            }
        }
        fail("unterminated string");
    }
    JValue number() {
        const std::size_t b = i_;
        auto digits = [&] {
            const std::size_t d = i_;
            while (i_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_]))) ++i_;
            return i_ - d;
        };
        if (i_ < s_.size() && s_[i_] == '-') ++i_;
        if (i_ < s_.size() && s_[i_] == '0') ++i_;
        else if (digits() == 0) fail("expected a value");
        if (i_ < s_.size() && s_[i_] == '.') {
            ++i_;
            if (digits() == 0) fail("digits expected after '.'");
        }
        if (i_ < s_.size() && (s_[i_] == 'e' || s_[i_] == 'E')) {
            ++i_;
            if (i_ < s_.size() && (s_[i_] == '+' || s_[i_] == '-')) ++i_;
            if (digits() == 0) fail("digits expected in exponent");
        }
        JValue v;
        v.kind = JValue::Number;
        v.num = std::strtod(s_.substr(b, i_ - b).c_str(), nullptr);
        return v;
    }

    const std::string& s_;
    std::size_t i_ = 0;
};

ExtractionReport sampleReport() {
    ExtractionReport r;
    r.input.vertices = 27;
    r.input.tets = 48;
    r.input.boundary_faces = 48;
    r.input.parametric_volume = 27.000000000000004;
    r.output.vertices = 64;
    r.output.hexes = 27;
    r.output.quads = 108;
    r.output.boundary_quads = 54;
    r.darts.extracted = 1296;
    r.valid_all_hex = true;
    r.timings_s.preprocess = 0.001;
    r.threads = 4;
    r.warnings = {"quote \" backslash \\ newline \n tab \t bell \a end"};
    return r;
}

void expectNumber(const JValue& obj, const std::string& key) {
    const JValue* v = obj.get(key);
    ASSERT_NE(v, nullptr) << "missing key " << key;
    EXPECT_EQ(v->kind, JValue::Number) << "key " << key << " is not a number";
}

} // namespace

TEST(ReportJsonTest, ParserSelfCheck) {
    EXPECT_NO_THROW(JParser("{\"a\": [1, -2.5e3, true, null, \"x\\u0041\"]}").parseDocument());
    EXPECT_THROW(JParser("{\"a\": 1,}").parseDocument(), std::runtime_error);
    EXPECT_THROW(JParser("{\"a\": \"1\n\"}").parseDocument(), std::runtime_error);
    EXPECT_THROW(JParser("{\"a\": nan}").parseDocument(), std::runtime_error);
    EXPECT_THROW(JParser("{\"a\": 01}").parseDocument(), std::runtime_error);
    EXPECT_THROW(JParser("[1] 2").parseDocument(), std::runtime_error);
}

TEST(ReportJsonTest, RequiredStructureAndTypes) {
    ReportExtras x;
    x.read_s = 0.5;
    x.write_s = 0.25;
    x.total_s = 1.0;
    x.quality.min_scaled_jacobian = 1;
    x.quality.mean_scaled_jacobian = 1;
    x.warnings = {"out.mesh: 2 non-hex cells left out"};
    const std::string json = reportToJson(sampleReport(), x);
    JValue doc;
    ASSERT_NO_THROW(doc = JParser(json).parseDocument()) << json;
    ASSERT_EQ(doc.kind, JValue::Object);

    const std::map<std::string, std::vector<std::string>> required = {
        {"input", {"vertices", "tets", "boundary_faces", "flipped_tets", "degenerate_tets", "singular_edges",
                   "parametric_volume"}},
        {"output", {"vertices", "hexes", "non_hex_cells", "quads", "boundary_quads", "unconnected_darts"}},
        {"darts", {"extracted", "anti", "annihilated_pairs"}},
        {"quality", {"min_scaled_jacobian", "mean_scaled_jacobian", "inverted_hexes", "invalid_hexes",
                     "undecided_hexes"}},
        {"timings_s", {"read", "preprocess", "vertices", "darts", "connect", "postprocess", "assemble", "write", "total"}},
    };
    for (const auto& sec : required) {
        const JValue* o = doc.get(sec.first);
        ASSERT_NE(o, nullptr) << "missing section " << sec.first;
        ASSERT_EQ(o->kind, JValue::Object);
        for (const auto& k : sec.second) expectNumber(*o, k);
    }
    ASSERT_NE(doc.get("valid_all_hex"), nullptr);
    EXPECT_EQ(doc.get("valid_all_hex")->kind, JValue::Bool);
    EXPECT_TRUE(doc.get("valid_all_hex")->b);
    expectNumber(doc, "threads");
    EXPECT_EQ(doc.get("threads")->num, 4);
    ASSERT_NE(doc.get("version"), nullptr);
    EXPECT_EQ(doc.get("version")->kind, JValue::String);
    EXPECT_EQ(doc.get("version")->str, version());

    EXPECT_EQ(doc.get("output")->get("hexes")->num, 27);
    EXPECT_EQ(doc.get("input")->get("parametric_volume")->num, 27.000000000000004);  // round trip
    EXPECT_EQ(doc.get("timings_s")->get("read")->num, 0.5);
    EXPECT_EQ(doc.get("timings_s")->get("write")->num, 0.25);
    EXPECT_EQ(doc.get("timings_s")->get("total")->num, 1.0);

    const JValue* w = doc.get("warnings");
    ASSERT_NE(w, nullptr);
    ASSERT_EQ(w->kind, JValue::Array);
    ASSERT_EQ(w->items.size(), 2u);
    EXPECT_EQ(w->items[0].str, sampleReport().warnings[0]);  // escaping round-trips
    EXPECT_EQ(w->items[1].str, x.warnings[0]);
    ASSERT_NE(doc.get("validation"), nullptr);
    EXPECT_EQ(doc.get("validation")->get("valid")->kind, JValue::Bool);
}

TEST(ReportJsonTest, NonFiniteNumbersBecomeNull) {
    ExtractionReport r = sampleReport();
    r.input.parametric_volume = std::numeric_limits<double>::quiet_NaN();
    ReportExtras x;
    x.quality.min_scaled_jacobian = std::numeric_limits<double>::infinity();
    x.total_s = -std::numeric_limits<double>::infinity();
    const std::string json = reportToJson(r, x);
    JValue doc;
    ASSERT_NO_THROW(doc = JParser(json).parseDocument()) << json;
    EXPECT_EQ(doc.get("input")->get("parametric_volume")->kind, JValue::Null);
    EXPECT_EQ(doc.get("quality")->get("min_scaled_jacobian")->kind, JValue::Null);
    EXPECT_EQ(doc.get("timings_s")->get("total")->kind, JValue::Null);
    EXPECT_EQ(json.find("nan"), std::string::npos);
    EXPECT_EQ(json.find("inf"), std::string::npos);
}

TEST(ReportJsonTest, EmptyReportIsValidJson) {
    const std::string json = reportToJson(ExtractionReport(), ReportExtras());
    JValue doc;
    ASSERT_NO_THROW(doc = JParser(json).parseDocument()) << json;
    EXPECT_FALSE(doc.get("valid_all_hex")->b);
    EXPECT_EQ(doc.get("warnings")->items.size(), 0u);
}

TEST(ReportJsonTest, QuoteAndNumberHelpers) {
    EXPECT_EQ(jsonQuote("a\"b\\c\n\x01"), "\"a\\\"b\\\\c\\n\\u0001\"");
    EXPECT_EQ(jsonNumber(0.1), "0.1");
    EXPECT_EQ(jsonNumber(-0.0), "0");
    EXPECT_EQ(jsonNumber(1e300), "1e+300");
    EXPECT_EQ(jsonNumber(std::nan("")), "null");
}
