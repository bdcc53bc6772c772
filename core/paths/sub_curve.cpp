#include "paths/sub_curve.h"

namespace chaplygin {

SubCurve::SubCurve(std::shared_ptr<const Curve> whole, double ua, double ub)
    : m_whole(std::move(whole)), m_ua(ua), m_ub(ub) {}

std::vector<double> SubCurve::breakpoints() const {
    std::vector<double> all = m_whole->breakpoints(), inside;
    if (all.size() < 2)
        return {};
    inside.push_back(m_ua);
    for (double u : all)
        if (u > m_ua && u < m_ub)
            inside.push_back(u);
    inside.push_back(m_ub);
    return inside;
}

} // namespace chaplygin
