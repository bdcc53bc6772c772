#include "paths/spline_curve.h"

#include "common/input_error.h"

#include <algorithm>
#include <cmath>

namespace chaplygin {

SplineCurve::SplineCurve(const std::vector<double>& x, const std::vector<double>& y,
                         double bandwidth, Ends ends)
    : m_ends(ends) {
    if (x.size() != y.size() || x.size() < 3)
        throw InputError("points", "a smoothed path needs at least 3 distinct points");
    m_knots.resize(x.size());
    m_knots[0] = 0;
    for (std::size_t i = 1; i < x.size(); ++i)
        m_knots[i] = m_knots[i - 1] + std::hypot(x[i] - x[i - 1], y[i] - y[i - 1]);
    double h = m_knots.back() / static_cast<double>(x.size() - 1);
    double alpha = bandwidth > 0 ? std::pow(bandwidth * h, 4) / h : 0.0;
    const Factor f = factor(alpha);
    const Coordinate cx = smooth(x, alpha, f), cy = smooth(y, alpha, f);
    // each interval's cubic from the values g and second derivatives gamma at its ends (Green
    // and Silverman eq. 2.4), in powers of the distance from its first knot
    m_pieces.resize(x.size() - 1);
    auto powers = [](const Coordinate& c, std::size_t i, double h, double* out) {
        const double gi = c.g[i], gj = c.g[i + 1], ci = c.gamma[i], cj = c.gamma[i + 1];
        out[0] = gi;
        out[1] = (gj - gi) / h - h / 6.0 * (2 * ci + cj);
        out[2] = ci / 2;
        out[3] = (cj - ci) / (6 * h);
    };
    for (std::size_t i = 0; i + 1 < x.size(); ++i) {
        const double h = m_knots[i + 1] - m_knots[i];
        powers(cx, i, h, m_pieces[i].cx);
        powers(cy, i, h, m_pieces[i].cy);
    }
}

SplineCurve::Factor SplineCurve::factor(double alpha) const {
    // (R + alpha Q^T W^-1 Q) gamma = Q^T y, g = y - alpha W^-1 Q gamma (Green and Silverman,
    // eq. 2.15, weighted), W^-1 = diag(looseness): only the diagonal meets the ends' weights.
    // R and Q^T Q are banded (Q has three entries per column), so the matrix is pentadiagonal and
    // LDL^T keeps the band (Green and Silverman §2.3.3: the Reinsch algorithm)
    const int n = static_cast<int>(m_knots.size()), m = n - 2;
    Factor f;
    f.invH.resize(n - 1);
    for (int i = 0; i + 1 < n; ++i)
        f.invH[i] = 1 / (m_knots[i + 1] - m_knots[i]);
    const std::vector<double>& r = f.invH;
    // column j of Q (interior knot j + 1): r_j at row j, -(r_j + r_{j+1}) at j + 1, r_{j+1} at j +
    // 2
    auto diag = [&](int j) {
        const double mid = r[j] + r[j + 1];
        const auto u = static_cast<std::size_t>(j);
        return (1 / r[j] + 1 / r[j + 1]) / 3 +
               alpha * (r[j] * r[j] * looseness(u) + mid * mid * looseness(u + 1) +
                        r[j + 1] * r[j + 1] * looseness(u + 2));
    };
    auto next = [&](int j) { // entry (j, j + 1)
        return 1 / (6 * r[j + 1]) - alpha * r[j + 1] * (r[j] + 2 * r[j + 1] + r[j + 2]);
    };
    auto second = [&](int j) { return alpha * r[j + 1] * r[j + 2]; }; // entry (j, j + 2)
    f.d.assign(m, 0.0);
    f.l1.assign(m, 0.0);
    f.l2.assign(m, 0.0);
    for (int j = 0; j < m; ++j) {
        double d = diag(j);
        if (j >= 1)
            d -= f.l1[j - 1] * f.l1[j - 1] * f.d[j - 1];
        if (j >= 2)
            d -= f.l2[j - 2] * f.l2[j - 2] * f.d[j - 2];
        if (!(d > 0) || !std::isfinite(d))
            throw InputError("points",
                             "the smoothing spline could not be fitted (repeated points?)");
        f.d[j] = d;
        if (j + 1 < m)
            f.l1[j] = (next(j) - (j >= 1 ? f.l2[j - 1] * f.l1[j - 1] * f.d[j - 1] : 0.0)) / d;
        if (j + 2 < m)
            f.l2[j] = second(j) / d;
    }
    return f;
}

SplineCurve::Coordinate SplineCurve::smooth(const std::vector<double>& data, double alpha,
                                            const Factor& f) const {
    const int n = static_cast<int>(data.size()), m = n - 2;
    const std::vector<double>& r = f.invH;
    std::vector<double> z(m);
    for (int j = 0; j < m; ++j) { // L z = Q^T y
        double v = r[j] * data[j] - (r[j] + r[j + 1]) * data[j + 1] + r[j + 1] * data[j + 2];
        if (j >= 1)
            v -= f.l1[j - 1] * z[j - 1];
        if (j >= 2)
            v -= f.l2[j - 2] * z[j - 2];
        z[j] = v;
    }
    Coordinate c;
    c.gamma.assign(n, 0.0);            // by knot; natural ends: g'' = 0 at the first and last
    for (int j = m - 1; j >= 0; --j) { // D L^T gamma = z
        double v = z[j] / f.d[j];
        if (j + 1 < m)
            v -= f.l1[j] * c.gamma[j + 2];
        if (j + 2 < m)
            v -= f.l2[j] * c.gamma[j + 3];
        c.gamma[j + 1] = v;
    }
    // g = y - alpha W^-1 Q gamma: row i of Q meets the second derivatives at knots i - 1, i, i + 1
    c.g.resize(n);
    for (int i = 0; i < n; ++i) {
        double q = 0;
        if (i + 1 < n)
            q += r[i] * c.gamma[i + 1];
        if (i >= 1)
            q += r[i - 1] * c.gamma[i - 1];
        if (i >= 1 && i + 1 < n)
            q -= (r[i - 1] + r[i]) * c.gamma[i];
        c.g[i] = data[i] - alpha * looseness(static_cast<std::size_t>(i)) * q;
    }
    return c;
}

CurvePoint SplineCurve::eval(double u) const {
    // a table asks for points of one knot interval in turn: try this thread's last one first
    thread_local const SplineCurve* lastCurve = nullptr;
    thread_local std::size_t last = 0;
    int i;
    if (lastCurve == this && last + 1 < m_knots.size() && u >= m_knots[last] &&
        u < m_knots[last + 1]) {
        i = static_cast<int>(last);
    } else {
        auto it = std::upper_bound(m_knots.begin(), m_knots.end(), u);
        i = std::clamp(static_cast<int>(it - m_knots.begin()) - 1, 0,
                       static_cast<int>(m_knots.size()) - 2);
        lastCurve = this;
        last = static_cast<std::size_t>(i);
    }
    const Piece& c = m_pieces[static_cast<std::size_t>(i)];
    const double a = u - m_knots[static_cast<std::size_t>(i)];
    CurvePoint p;
    p.x = c.cx[0] + a * (c.cx[1] + a * (c.cx[2] + a * c.cx[3]));
    p.y = c.cy[0] + a * (c.cy[1] + a * (c.cy[2] + a * c.cy[3]));
    p.dx = c.cx[1] + a * (2 * c.cx[2] + 3 * a * c.cx[3]);
    p.dy = c.cy[1] + a * (2 * c.cy[2] + 3 * a * c.cy[3]);
    p.ddx = 2 * c.cx[2] + 6 * a * c.cx[3];
    p.ddy = 2 * c.cy[2] + 6 * a * c.cy[3];
    p.dddx = 6 * c.cx[3];
    p.dddy = 6 * c.cy[3];
    return p;
}

} // namespace chaplygin
