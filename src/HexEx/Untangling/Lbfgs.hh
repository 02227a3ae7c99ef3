#pragma once
/// @file Lbfgs.hh
/// @ingroup quality
/// A small limited-memory BFGS minimiser (Nocedal and Wright, "Numerical Optimization",
/// algorithm 7.4, two-loop recursion) with a backtracking Armijo line search, on Eigen
/// vectors. Deterministic: the same function gives the same iterates.

#include <Eigen/Core>

#include <functional>

namespace HexEx {

/// Objective for minimizeLbfgs(): returns f(x) and writes the gradient into the second argument.
using LbfgsObjective = std::function<double(const Eigen::VectorXd&, Eigen::VectorXd&)>;

/// Settings of minimizeLbfgs().
struct LbfgsOptions {
    int history = 10;              ///< number of stored correction pairs
    int max_iterations = 200;      ///< iterations (line searches) at most
    double gradient_tolerance = 1e-8;  ///< stop when |g|_inf <= this
    double relative_decrease = 1e-9;   ///< stop when an iteration decreases f by less than this times |f|
};

/// What minimizeLbfgs() did.
struct LbfgsResult {
    double value = 0;    ///< f at the returned point
    int iterations = 0;  ///< iterations done
    int evaluations = 0; ///< calls of the objective
};

/// Minimises @p f starting from @p x (overwritten with the best point found).
LbfgsResult minimizeLbfgs(const LbfgsObjective& f, Eigen::VectorXd& x, const LbfgsOptions& options = {});

} // namespace HexEx
