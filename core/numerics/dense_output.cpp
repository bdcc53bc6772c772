#include "numerics/dense_output.h"

#include <algorithm>

namespace chaplygin {

void DenseOutput::add(const OdeProblem& problem, double t, const double* y, const double* f,
                      OdeWork& work) {
    std::array<double, kMaxOdeDimension * kMaxOdeDimension> jac{};
    Row dfdt{}, yr{}, fr{}, gr{};
    problem.jacobian(t, y, jac.data(), dfdt.data());
    ++work.jacobianEvals;
    for (int i = 0; i < m_dim; ++i) {
        yr[i] = y[i];
        fr[i] = f[i];
        // y'' = (df/dy) y' + df/dt
        double g = dfdt[i];
        for (int j = 0; j < m_dim; ++j)
            g += jac[i * m_dim + j] * f[j];
        gr[i] = g;
    }
    m_t.push_back(t);
    m_y.push_back(yr);
    m_f.push_back(fr);
    m_g.push_back(gr);
}

void DenseOutput::reserve(std::size_t nodes) {
    m_t.reserve(nodes);
    m_y.reserve(nodes);
    m_f.reserve(nodes);
    m_g.reserve(nodes);
}

std::size_t DenseOutput::nodeBefore(double t) const {
    auto it = std::upper_bound(m_t.begin(), m_t.end(), t);
    return it == m_t.begin() ? 0 : static_cast<std::size_t>(it - m_t.begin()) - 1;
}

void DenseOutput::at(double t, double* out) const {
    if (m_t.size() == 1 || t <= m_t.front()) {
        std::copy_n(m_y.front().begin(), m_dim, out);
        return;
    }
    if (t >= m_t.back()) {
        std::copy_n(m_y.back().begin(), m_dim, out);
        return;
    }
    auto it = std::upper_bound(m_t.begin(), m_t.end(), t);
    std::size_t k = static_cast<std::size_t>(it - m_t.begin()) - 1;
    const double h = m_t[k + 1] - m_t[k];
    const double s = (t - m_t[k]) / h;
    const double s2 = s * s, s3 = s2 * s, s4 = s3 * s, s5 = s4 * s;
    // quintic Hermite basis on [0, 1]
    const double h00 = 1 - 10 * s3 + 15 * s4 - 6 * s5;
    const double h01 = 10 * s3 - 15 * s4 + 6 * s5;
    const double h10 = s - 6 * s3 + 8 * s4 - 3 * s5;
    const double h11 = -4 * s3 + 7 * s4 - 3 * s5;
    const double h20 = 0.5 * (s2 - 3 * s3 + 3 * s4 - s5);
    const double h21 = 0.5 * (s3 - 2 * s4 + s5);
    for (int i = 0; i < m_dim; ++i)
        out[i] = h00 * m_y[k][i] + h01 * m_y[k + 1][i] +
                 h * (h10 * m_f[k][i] + h11 * m_f[k + 1][i]) +
                 h * h * (h20 * m_g[k][i] + h21 * m_g[k + 1][i]);
}

} // namespace chaplygin
