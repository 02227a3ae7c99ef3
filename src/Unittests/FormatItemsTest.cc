/// @file FormatItemsTest.cc
/// detail::formatItems() (pieces formatted on worker threads, appended in order by the
/// caller) and the line helpers of detail::BlockOutput: the same bytes for any thread count
/// and block size, errors of the formatter and of the sink rethrown without a hang.

#include <HexEx/IO/BlockOutput.hh>
#include <gtest/gtest.h>

#include <climits>
#include <cstddef>
#include <sstream>
#include <stdexcept>
#include <streambuf>
#include <string>
#include <vector>

using namespace HexEx;

namespace {

/// Item @p i as text: a line of a few numbers whose length varies with i.
void formatItem(detail::BlockOutput& o, std::size_t i) {
    o << i;
    for (std::size_t k = 0; k < i % 5; ++k) o << ' ' << static_cast<int>(i * 7 + k) - 1000;
    o << '\n';
}

/// All @p n items appended one after the other on this thread.
std::string serial(std::size_t n) {
    detail::BlockOutput o;
    for (std::size_t i = 0; i < n; ++i) formatItem(o, i);
    return o.take();
}

/// A stream buffer that fails every write after the first @p okBytes bytes.
class FailingBuffer : public std::streambuf {
public:
    explicit FailingBuffer(std::size_t okBytes) : left_(okBytes) {}

protected:
    std::streamsize xsputn(const char*, std::streamsize n) override {
        if (static_cast<std::size_t>(n) > left_) return 0;
        left_ -= static_cast<std::size_t>(n);
        return n;
    }
    int_type overflow(int_type) override { return traits_type::eof(); }

private:
    std::size_t left_;
};

} // namespace

// 300,007 items are 37 pieces of 2^13: with 2 threads (4 buffer slots) several rounds.
TEST(FormatItems, SameBytesForAnyThreadCountAndBlockSize) {
    const std::size_t n = 300007;
    const std::string expected = serial(n);
    for (const int threads : {1, 2, 3, 5})
        for (const std::size_t block : {std::size_t(1) << 20, std::size_t(1000)}) {
            if (block == 1000 && threads != 2) continue;
            std::ostringstream out;
            detail::BlockOutput o(&out, block);
            o << "head\n";
            detail::formatItems(o, n, threads, formatItem);
            o << "tail\n";
            o.flush();
            EXPECT_EQ(out.str(), "head\n" + expected + "tail\n") << threads << " threads, block " << block;
        }
    detail::BlockOutput memory;  // no sink: everything kept in memory
    detail::formatItems(memory, n, 2, formatItem);
    EXPECT_EQ(memory.take(), expected);
}

TEST(FormatItems, FormatterErrorIsRethrown) {
    for (const int threads : {2, 3}) {
        std::ostringstream out;
        detail::BlockOutput o(&out);
        const auto failing = [](detail::BlockOutput& t, std::size_t i) {
            if (i == 500000) throw std::runtime_error("item 500000 failed");
            formatItem(t, i);
        };
        try {
            detail::formatItems(o, 1000000, threads, failing);
            FAIL() << "no exception with " << threads << " threads";
        } catch (const std::runtime_error& e) {
            EXPECT_STREQ(e.what(), "item 500000 failed");
        }
    }
}

TEST(FormatItems, SinkErrorIsRethrown) {
    FailingBuffer buffer(3000000);
    std::ostream out(&buffer);
    out.exceptions(std::ios::badbit);
    detail::BlockOutput o(&out);
    EXPECT_THROW(detail::formatItems(o, 1000000, 2, formatItem), std::ios_base::failure);
}

TEST(FormatItems, IntLineAndIntPairAsOneByOne) {
    std::vector<int> values = {0, 7, -1, 10, 99, 100, 12345678, INT_MAX, INT_MIN, -2147483647, 4294, 100000000};
    for (int i = 0; i < 40; ++i) values.push_back(i * 1234567 - 20000000);
    for (std::size_t len : {std::size_t(0), std::size_t(1), std::size_t(4), std::size_t(20), std::size_t(21),
                            values.size()}) {
        detail::BlockOutput fast(nullptr, 16), slow(nullptr, 16);
        fast.intLine(values.data(), values.data() + len);
        slow << len;
        for (std::size_t k = 0; k < len; ++k) slow << ' ' << values[k];
        slow << '\n';
        EXPECT_EQ(fast.take(), slow.take()) << len << " numbers";
    }
    for (std::size_t k = 0; k + 1 < values.size(); ++k) {
        detail::BlockOutput fast(nullptr, 16), slow(nullptr, 16);
        fast.intPair(values[k], values[k + 1]);
        slow << values[k] << ' ' << values[k + 1] << '\n';
        EXPECT_EQ(fast.take(), slow.take());
    }
}
