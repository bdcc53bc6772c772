#pragma once
// The set-up the Plan tool's tests share (docs/physics.md §10): a window on a straight drawn path
// for every test function, and the planned knife integrated here by classical RK4, an independent
// reference for the drawn tracks and the plotted curves (not the closed form the tool draws).
#include "canvas/plan_tool.h"
#include "canvas/scene_canvas.h"
#include "classical_rk4.h"
#include "document/scene_document.h"
#include "gui_test_support.h"
#include "shell/main_window.h"

#include <QtTest>

#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

namespace chaplygin::ui::test {

struct Knife {
    double x, y, phi, psi, lambda;
};

// the knife's motion, x' = v sin Psi cos phi, y' = v sin Psi sin phi, phi' = v cos Psi / b,
// Psi' = Lambda, Lambda' = -(v^2 / 2 b^2) sin 2 Psi, by classical RK4 in n steps to time t
inline std::vector<Knife> integrateKnife(Knife k, double b, double v, double t, int n) {
    auto rate = [&](const Knife& s) {
        return Knife{v * std::sin(s.psi) * std::cos(s.phi), v * std::sin(s.psi) * std::sin(s.phi),
                     v * std::cos(s.psi) / b, s.lambda, -v * v / (2 * b * b) * std::sin(2 * s.psi)};
    };
    return reference::classicalRk4(
        k, std::array{&Knife::x, &Knife::y, &Knife::phi, &Knife::psi, &Knife::lambda}, rate, t, n);
}

inline double angleMiss(double a, double b) {
    return std::abs(std::remainder(a - b, 2 * std::numbers::pi));
}

/// Used as a base of a QtTest class, whose initTestCase, init and cleanup slots call
/// startSuite, openPlanWindow and closeWindow.
class PlanToolFixture {
  protected:
    /// settingsName: the test's own QSettings application name.
    void startSuite(const char* settingsName) {
        useTestSettings(QString::fromLatin1(settingsName));
    }
    /// A window (showTestWindow) on straightScene(), with its canvas and its Plan tool.
    void openPlanWindow() {
        m_window = showTestWindow();
        QVERIFY(m_window);
        m_window->document()->loadNow(straightScene());
        m_canvas = m_window->canvas();
        m_tool = m_canvas->planTool();
        QVERIFY(m_tool);
    }
    void closeWindow() { m_window.reset(); }

    std::unique_ptr<MainWindow> m_window;
    SceneCanvas* m_canvas = nullptr;
    PlanTool* m_tool = nullptr;
};

} // namespace chaplygin::ui::test
