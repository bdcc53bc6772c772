#include "panels/equations_panel.h"

#include "document/math_text.h"
#include "document/scene_document.h"
#include "panels/equations_html.h"
#include "scene/scene_plan.h"

#include <QScrollBar>
#include <QTextBrowser>
#include <QVBoxLayout>

#include <algorithm>
#include <exception>

namespace chaplygin::ui {

EquationsPanel::EquationsPanel(SceneDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    m_view = new QTextBrowser;
    m_view->setObjectName(QStringLiteral("equationsView"));
    layout->addWidget(m_view);
    m_basePoints = m_view->font().pointSizeF();
    connect(document, &SceneDocument::solutionChanged, this, &EquationsPanel::refresh);
}

void EquationsPanel::setTime(double t) {
    m_time = t;
    refresh();
}

void EquationsPanel::refresh() {
    m_stale = true;
    // while hidden (a closed dock) or off screen (a background tab: Qt moves it out of the
    // window rather than hiding it) the page waits until it is shown
    if (isVisible() && !visibleRegion().isEmpty())
        html();
}

QString EquationsPanel::html() {
    if (!m_stale)
        return m_html;
    m_stale = false;
    const auto& solution = m_document->solution();
    m_html = solution ? equationsHtml(*solution, m_time) : QString();
    if (solution && !m_html.isEmpty())
        m_html.insert(m_html.lastIndexOf(QStringLiteral("</body>")), planSection(*solution));
    int scroll = m_view->verticalScrollBar()->value();
    m_view->setHtml(withDottedSymbolFont(m_html)); // the dots of φ̇, Ψ̇ on their letters
    m_view->verticalScrollBar()->setValue(scroll);
    return m_html;
}

QString EquationsPanel::planSection(const Solution& solution) {
    const auto& plan = m_document->scene().plan;
    if (!plan)
        return {};
    // planned again only when the plan or the solution changed, not at every frame
    if (!(m_planOf == plan) || m_plannedFor.get() != &solution) {
        m_planOf = plan;
        m_plannedFor = m_document->solution();
        m_planned = {};
        try {
            m_request = planRequestOf(*plan, solution);
            m_planned = planVakonomic(m_request);
        } catch (const std::exception&) {
            // no section: the Plan tool says why
        }
    }
    const int n = int(m_planned.geodesics.size());
    if (plan->choice < 0 || plan->choice >= n)
        return {};
    return planHtml(m_request, m_planned.geodesics[std::size_t(plan->choice)], plan->choice, n,
                    m_time);
}

void EquationsPanel::setFontScale(double scale) {
    QFont f = m_view->font();
    f.setPointSizeF(m_basePoints * std::clamp(scale, 0.5, 6.0));
    m_view->setFont(f);
    m_view->document()->setDefaultFont(f);
    m_stale = true;
    html();
}

void EquationsPanel::showEvent(QShowEvent* e) {
    QWidget::showEvent(e);
    html();
}

} // namespace chaplygin::ui
