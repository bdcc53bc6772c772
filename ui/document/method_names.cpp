#include "document/method_names.h"

#include <QCoreApplication>

#include <array>
#include <utility>

namespace chaplygin::ui {

QString plainMethodName(const std::string& id) {
    static const std::array<std::pair<const char*, const char*>, 13> names = {{
        {"closed_form", QT_TRANSLATE_NOOP("MethodNames", "Exact formula (the app's)")},
        {"quadrature_gauss_newton",
         QT_TRANSLATE_NOOP("MethodNames", "Quadrature along the path (the app's)")},
        {"gsl_qag_newton", QT_TRANSLATE_NOOP("MethodNames", "Adaptive quadrature (GSL)")},
        {"gsl_rk4", QT_TRANSLATE_NOOP("MethodNames", "Runge\u2013Kutta 4 (GSL)")},
        {"gsl_rkf45", QT_TRANSLATE_NOOP("MethodNames", "Runge\u2013Kutta\u2013"
                                                       "Fehlberg 4(5) (GSL)")},
        {"gsl_rkck", QT_TRANSLATE_NOOP("MethodNames", "Runge\u2013Kutta Cash\u2013Karp (GSL)")},
        {"gsl_rk8pd", QT_TRANSLATE_NOOP("MethodNames", "Runge\u2013Kutta Prince\u2013"
                                                       "Dormand 8 (GSL)")},
        {"gsl_msadams", QT_TRANSLATE_NOOP("MethodNames", "Multistep Adams (GSL)")},
        {"gsl_msbdf", QT_TRANSLATE_NOOP("MethodNames", "Multistep BDF (GSL)")},
        {"rk4_classical", QT_TRANSLATE_NOOP("MethodNames", "Classical Runge\u2013Kutta 4")},
        {"rk4_energy_projection",
         QT_TRANSLATE_NOOP("MethodNames", "Runge\u2013Kutta 4, energy kept")},
        {"open_loop_gsl_rk8pd",
         QT_TRANSLATE_NOOP("MethodNames", "Paper's open loop, Runge\u2013Kutta 8 (GSL)")},
        {"open_loop_rk4_classical",
         QT_TRANSLATE_NOOP("MethodNames", "Paper's open loop, Runge\u2013Kutta 4")},
    }};
    for (const auto& [key, name] : names)
        if (id == key)
            return QCoreApplication::translate("MethodNames", name);
    return QString::fromStdString(id);
}

QString shortMethodName(const std::string& id) {
    static const std::array<std::pair<const char*, const char*>, 13> names = {{
        {"closed_form", QT_TRANSLATE_NOOP("MethodNames", "Exact formula")},
        {"quadrature_gauss_newton", QT_TRANSLATE_NOOP("MethodNames", "Path quadrature")},
        {"gsl_qag_newton", QT_TRANSLATE_NOOP("MethodNames", "QAG (GSL)")},
        {"gsl_rk4", QT_TRANSLATE_NOOP("MethodNames", "RK4 (GSL)")},
        {"gsl_rkf45", QT_TRANSLATE_NOOP("MethodNames", "RKF45 (GSL)")},
        {"gsl_rkck", QT_TRANSLATE_NOOP("MethodNames", "Cash\u2013Karp (GSL)")},
        {"gsl_rk8pd", QT_TRANSLATE_NOOP("MethodNames", "RK8PD (GSL)")},
        {"gsl_msadams", QT_TRANSLATE_NOOP("MethodNames", "Adams (GSL)")},
        {"gsl_msbdf", QT_TRANSLATE_NOOP("MethodNames", "BDF (GSL)")},
        {"rk4_classical", QT_TRANSLATE_NOOP("MethodNames", "RK4")},
        {"rk4_energy_projection", QT_TRANSLATE_NOOP("MethodNames", "RK4, energy kept")},
        {"open_loop_gsl_rk8pd", QT_TRANSLATE_NOOP("MethodNames", "Open loop, RK8PD")},
        {"open_loop_rk4_classical", QT_TRANSLATE_NOOP("MethodNames", "Open loop, RK4")},
    }};
    for (const auto& [key, name] : names)
        if (id == key)
            return QCoreApplication::translate("MethodNames", name);
    return plainMethodName(id);
}

QString plainModelSummary(const Solution& solution) {
    const ModelReport& m = solution.models();
    const bool exactTime = m.timeLaw.rfind("closed form", 0) == 0;
    QString summary =
        exactTime ? QCoreApplication::translate("MethodNames", "Time along the path: exact formula")
                  : QCoreApplication::translate("MethodNames", "Time along the path: quadrature");
    summary +=
        QCoreApplication::translate("MethodNames", "; ghost and vakonomic body: formulas, no time "
                                                   "stepping");
    if (solution.perturbed())
        summary += QCoreApplication::translate("MethodNames",
                                               "; pushed bodies: Runge\u2013Kutta 8 integration");
    return summary;
}

QString technicalModel(const std::string& description) {
    return QCoreApplication::translate("ModelReport", description.c_str());
}

QString technicalModels(const Solution& solution) {
    const ModelReport& m = solution.models();
    QString text = QCoreApplication::translate(
                       "MethodNames", "path: %1\ntime law: %2\ns(t): %3\ncontrol: %4\n"
                                      "free velocities: %5\nfree position: %6\nvakonomic body: %7")
                       .arg(QString::fromStdString(m.path), technicalModel(m.timeLaw),
                            technicalModel(m.inversion), technicalModel(m.control),
                            technicalModel(m.freeVelocity), technicalModel(m.freePosition),
                            technicalModel(m.vakonomic));
    if (!m.perturbed.empty())
        text += QCoreApplication::translate("MethodNames", "\nopen loop: %1\nfeedback: %2")
                    .arg(QString::fromStdString(m.perturbed), QString::fromStdString(m.feedback));
    return text;
}

} // namespace chaplygin::ui
