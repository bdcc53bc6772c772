#include "paths/spline_curve.h"

#include "common/input_error.h"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>

namespace chaplygin {

SplineCurve::SplineCurve(const std::vector<double>& x, const std::vector<double>& y,
                         double bandwidth) {
    if (x.size() != y.size() || x.size() < 3)
        throw InputError("points", "a smoothed path needs at least 3 distinct points");
    m_knots.resize(x.size());
    m_knots[0] = 0;
    for (std::size_t i = 1; i < x.size(); ++i)
        m_knots[i] = m_knots[i - 1] + std::hypot(x[i] - x[i - 1], y[i] - y[i - 1]);
    double h = m_knots.back() / static_cast<double>(x.size() - 1);
    double alpha = bandwidth > 0 ? std::pow(bandwidth * h, 4) / h : 0.0;
    m_x = smooth(x, alpha);
    m_y = smooth(y, alpha);
}

// (R + alpha Q^T Q) gamma = Q^T y, g = y - alpha Q gamma (Green and Silverman, eq. 2.15)
SplineCurve::Coordinate SplineCurve::smooth(const std::vector<double>& data, double alpha) const {
    const int n = static_cast<int>(data.size());
    const int m = n - 2;
    std::vector<double> h(n - 1);
    for (int i = 0; i + 1 < n; ++i)
        h[i] = m_knots[i + 1] - m_knots[i];
    Eigen::SparseMatrix<double> q(n, m), r(m, m);
    std::vector<Eigen::Triplet<double>> qt, rt;
    for (int j = 0; j < m; ++j) {
        // column j belongs to interior knot j + 1
        qt.emplace_back(j, j, 1.0 / h[j]);
        qt.emplace_back(j + 1, j, -1.0 / h[j] - 1.0 / h[j + 1]);
        qt.emplace_back(j + 2, j, 1.0 / h[j + 1]);
        rt.emplace_back(j, j, (h[j] + h[j + 1]) / 3.0);
        if (j + 1 < m) {
            rt.emplace_back(j, j + 1, h[j + 1] / 6.0);
            rt.emplace_back(j + 1, j, h[j + 1] / 6.0);
        }
    }
    q.setFromTriplets(qt.begin(), qt.end());
    r.setFromTriplets(rt.begin(), rt.end());
    Eigen::VectorXd yv = Eigen::Map<const Eigen::VectorXd>(data.data(), n);
    Eigen::SparseMatrix<double> a = r + alpha * Eigen::SparseMatrix<double>(q.transpose() * q);
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(a);
    if (solver.info() != Eigen::Success)
        throw InputError("points", "the smoothing spline could not be fitted (repeated points?)");
    Eigen::VectorXd gamma = solver.solve(q.transpose() * yv);
    Eigen::VectorXd g = yv - alpha * (q * gamma);
    Coordinate c;
    c.g.assign(g.data(), g.data() + n);
    c.gamma.assign(n, 0.0);
    for (int j = 0; j < m; ++j)
        c.gamma[j + 1] = gamma[j];
    return c;
}

void SplineCurve::evalCoordinate(const Coordinate& c, int i, double u, double* v, double* d1,
                                 double* d2, double* d3) const {
    // cubic on [t_i, t_{i+1}] from values g and second derivatives gamma (G&S eq. 2.4)
    double h = m_knots[i + 1] - m_knots[i];
    double a = u - m_knots[i], b = m_knots[i + 1] - u;
    double gi = c.g[i], gj = c.g[i + 1], ci = c.gamma[i], cj = c.gamma[i + 1];
    *v = (a * gj + b * gi) / h - a * b / 6.0 * ((1 + a / h) * cj + (1 + b / h) * ci);
    *d1 = (gj - gi) / h - h / 6.0 * (2 * ci + cj) + ci * a + (cj - ci) * a * a / (2 * h);
    *d2 = ci + (cj - ci) * a / h;
    *d3 = (cj - ci) / h;
}

CurvePoint SplineCurve::eval(double u) const {
    auto it = std::upper_bound(m_knots.begin(), m_knots.end(), u);
    int i = std::clamp(static_cast<int>(it - m_knots.begin()) - 1, 0,
                       static_cast<int>(m_knots.size()) - 2);
    CurvePoint p;
    evalCoordinate(m_x, i, u, &p.x, &p.dx, &p.ddx, &p.dddx);
    evalCoordinate(m_y, i, u, &p.y, &p.dy, &p.ddy, &p.dddy);
    return p;
}

} // namespace chaplygin
