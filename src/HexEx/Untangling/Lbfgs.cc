/// @file Lbfgs.cc
/// L-BFGS two-loop recursion with a backtracking Armijo line search.

#include "Lbfgs.hh"

#include <cmath>
#include <vector>

namespace HexEx {

LbfgsResult minimizeLbfgs(const LbfgsObjective& f, Eigen::VectorXd& x, const LbfgsOptions& options) {
    LbfgsResult res;
    const Eigen::Index n = x.size();
    Eigen::VectorXd g(n), x_new(n), g_new(n), d(n);
    double fx = f(x, g);
    ++res.evaluations;
    const int m = options.history > 0 ? options.history : 1;
    std::vector<Eigen::VectorXd> s_hist, y_hist;
    std::vector<double> rho_hist;
    std::vector<double> alpha(static_cast<std::size_t>(m));
    int newest = -1, stored = 0;
    for (res.iterations = 0; res.iterations < options.max_iterations; ++res.iterations) {
        if (n == 0 || g.lpNorm<Eigen::Infinity>() <= options.gradient_tolerance) break;
        // Two-loop recursion: d = -H g.
        d = -g;
        for (int k = 0; k < stored; ++k) {
            const int i = (newest - k + m) % m;
            alpha[static_cast<std::size_t>(i)] = rho_hist[static_cast<std::size_t>(i)] * s_hist[static_cast<std::size_t>(i)].dot(d);
            d -= alpha[static_cast<std::size_t>(i)] * y_hist[static_cast<std::size_t>(i)];
        }
        if (stored > 0) {
            const auto& y = y_hist[static_cast<std::size_t>(newest)];
            d *= s_hist[static_cast<std::size_t>(newest)].dot(y) / y.squaredNorm();
        } else {
            d /= std::max(1.0, g.norm());  // first step: length at most 1
        }
        for (int k = stored - 1; k >= 0; --k) {
            const int i = (newest - k + m) % m;
            const double beta = rho_hist[static_cast<std::size_t>(i)] * y_hist[static_cast<std::size_t>(i)].dot(d);
            d += (alpha[static_cast<std::size_t>(i)] - beta) * s_hist[static_cast<std::size_t>(i)];
        }
        double slope = g.dot(d);
        if (!(slope < 0)) {  // not a descent direction: restart with steepest descent
            d = -g / std::max(1.0, g.norm());
            slope = g.dot(d);
            stored = 0;
        }
        // Backtracking line search (Armijo).
        double step = 1.0, f_new = 0;
        bool accepted = false;
        for (int ls = 0; ls < 40; ++ls) {
            x_new = x + step * d;
            f_new = f(x_new, g_new);
            ++res.evaluations;
            if (std::isfinite(f_new) && f_new <= fx + 1e-4 * step * slope) {
                accepted = true;
                break;
            }
            step *= 0.5;
        }
        if (!accepted) break;
        const double decrease = fx - f_new;
        Eigen::VectorXd s = x_new - x, y = g_new - g;
        x.swap(x_new);
        g.swap(g_new);
        fx = f_new;
        const double sy = s.dot(y);
        if (sy > 1e-16 * s.norm() * y.norm()) {
            newest = (newest + 1) % m;
            if (static_cast<int>(s_hist.size()) < m) {
                s_hist.push_back(std::move(s));
                y_hist.push_back(std::move(y));
                rho_hist.push_back(1.0 / sy);
            } else {
                s_hist[static_cast<std::size_t>(newest)] = std::move(s);
                y_hist[static_cast<std::size_t>(newest)] = std::move(y);
                rho_hist[static_cast<std::size_t>(newest)] = 1.0 / sy;
            }
            stored = std::min(stored + 1, m);
        }
        if (decrease <= options.relative_decrease * std::abs(fx)) {
            ++res.iterations;
            break;
        }
    }
    res.value = fx;
    return res;
}

} // namespace HexEx
