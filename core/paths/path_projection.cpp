#include "paths/path_projection.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace chaplygin {

PathFrame::PathFrame(std::shared_ptr<const PathTable> table, double phiOffset)
    : m_table(std::move(table)), m_phiOffset(phiOffset) {
    m_start = m_table->nodes().front();
    m_end = m_table->nodes().back();
    m_u0 = m_start.u;
    m_u1 = m_end.u;
}

PathPoint PathFrame::beyond(const PathNode& end, double u) const {
    // the osculating circle at the end, through the chord 2 sin(dphi/2)/kappa = ds sinc(dphi/2)
    PathPoint p;
    const double ds = end.speed * (u - end.u), dphi = end.kappa * ds, h = 0.5 * dphi;
    const double chord =
        std::fabs(h) < 1e-4 ? ds * (1 - h * h / 6 * (1 - h * h / 20)) : ds * std::sin(h) / h;
    const double phi = end.phi + m_phiOffset;
    p.u = u;
    p.s = end.s + ds;
    p.x = end.x + chord * std::cos(phi + h);
    p.y = end.y + chord * std::sin(phi + h);
    p.phi = phi + dphi;
    p.kappa = end.kappa;
    p.speed = end.speed;
    return p;
}

PathPoint PathFrame::at(double u) const {
    if (u < m_u0)
        return beyond(m_start, u);
    if (u > m_u1)
        return beyond(m_end, u);
    const PathTable& table = *m_table;
    const int k = table.panelOf(u);
    const double a = table.nodes()[k].u, b = table.nodes()[k + 1].u;
    const double xi = (2 * u - (a + b)) / (b - a);
    const PathNode n = table.interpolatedAt(k, xi);
    PathPoint p{n.u, n.s, n.x, n.y, n.phi + m_phiOffset, n.kappa, n.dkappa, 0, n.speed};
    if (!table.uniform() && table.chebPanels()[k].certified) {
        const auto rows = static_cast<std::size_t>(table.chebPanels()[k].degree) + 2;
        const double dxi = cheb::derivativeOne(table.coefficients(k), PathTable::kDkappa, xi, rows);
        p.ddkappa = dxi * 2 / ((b - a) * n.speed);
    }
    return p;
}

PathProjection PathFrame::project(double x, double y, double uGuess) const {
    double u = uGuess;
    PathPoint p = at(u);
    for (int i = 0; i < 50; ++i) {
        const double dx = x - p.x, dy = y - p.y, c = std::cos(p.phi), s = std::sin(p.phi);
        const double along = dx * c + dy * s, e = dy * c - dx * s;
        const double slope = p.speed * std::max(1 - p.kappa * e, 0.05);
        const double du = along / slope, ds = du * p.speed;
        if (std::fabs(ds) <= 1e-8) {
            // the last step to first order in ds: what it leaves is kappa ds^2 ~ 1e-16 m
            p.u += du;
            p.s += ds;
            p.x += c * ds;
            p.y += s * ds;
            p.phi += p.kappa * ds;
            p.kappa += p.dkappa * ds;
            p.dkappa += p.ddkappa * ds;
            return {p, e - p.kappa * ds * (along - ds)};
        }
        u += du;
        p = at(u);
    }
    throw PathProjectionError("no closest point on the path near u = " + std::to_string(uGuess));
}

} // namespace chaplygin
