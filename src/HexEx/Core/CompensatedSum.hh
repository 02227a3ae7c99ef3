#pragma once
/// @file CompensatedSum.hh
/// @ingroup kernel
/// Neumaier-compensated summation: sums of many terms (e.g. parametric volumes of a large
/// map) stay exact to the last digits.

#include <cmath>

namespace HexEx {

/// Running compensated sum.
class CompensatedSum {
public:
    /// Adds @p x.
    void add(double x) {
        const double t = sum_ + x;
        compensation_ += std::fabs(sum_) >= std::fabs(x) ? (sum_ - t) + x : (x - t) + sum_;
        sum_ = t;
    }
    /// The sum so far.
    double value() const { return sum_ + compensation_; }

private:
    double sum_ = 0, compensation_ = 0;
};

} // namespace HexEx
