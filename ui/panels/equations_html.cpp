#include "panels/equations_html.h"

#include "document/method_names.h"
#include "motion/vakonomic_motion.h"
#include "scene/body_vectors.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace chaplygin::ui {

namespace {

QString num(double v) {
    if (std::isinf(v))
        return v > 0 ? QStringLiteral("\u221e") : QStringLiteral("\u2212\u221e");
    if (std::fabs(v) < 5e-13)
        v = 0;
    QString s = QString::number(v, 'g', 4);
    return s.startsWith(u'-') ? QStringLiteral("\u2212") + s.mid(1) : s;
}

// a value inside a substituted formula: a negative one in parentheses, so that the line reads
// as it evaluates (1.6 \u00b7 (\u22120.8376), (\u22120.5009)\u00b2)
QString operand(double v) {
    const QString s = num(v);
    return s.startsWith(u'\u2212') ? QStringLiteral("(") + s + QStringLiteral(")") : s;
}

// one formula: the symbolic form, its substitution, the value with its unit and the source;
// a paragraph each, so that the page reads in a narrow dock
QString row(const QString& formula, const QString& substituted, double value, const QString& unit,
            const QString& source) {
    QString line = formula;
    if (!substituted.isEmpty())
        line += QStringLiteral(" = ") + substituted;
    return QStringLiteral("<p style='margin: 1px 0 5px 0'>%1 <b>= %2</b> %3<br>"
                          "<span style='color: #666'>%4</span></p>")
        .arg(line, num(value), unit, source);
}

QString section(const QString& title) {
    return QStringLiteral("<h4 style='margin: 8px 0 2px 0'>%1</h4>").arg(title);
}

QString systemLine(const Solution& s) {
    const Scene& scene = s.scene();
    const DerivedSystem& d = s.system();
    auto p = [&](const char* name) {
        auto it = scene.system.params.find(name);
        return it == scene.system.params.end() ? QStringLiteral("?") : num(it->second);
    };
    switch (scene.system.kind) {
    case SystemKind::Sleigh:
        return QCoreApplication::translate(
                   "EquationsPanel",
                   "<b>Chaplygin sleigh</b>: m = %1 kg, a = %2 m, b = %3 m "
                   "(b\u00b2 = a\u00b2 + I/m, b is the radius of gyration about P)")
            .arg(num(d.mass), num(d.a), num(d.b));
    case SystemKind::Disk:
        return QCoreApplication::translate(
                   "EquationsPanel",
                   "<b>Rolling disk</b> (App. A) as a sleigh: m_eff = m + I1/R\u00b2 = %1 kg, "
                   "b = R\u221a(I2/(I1 + mR\u00b2)) = %2 \u221a(%3/(%4 + %5\u00b7%2\u00b2)) = %6 m "
                   "(A14); the contact point is under the centre, so a = 0")
            .arg(num(d.mass), p("R"), p("I2"), p("I1"), p("m"), num(d.b));
    case SystemKind::Carriage:
        return QCoreApplication::translate("EquationsPanel",
                                           "<b>Two-wheeled carriage</b> (App. B) as a sleigh: "
                                           "m_eff = M + 2(m + I1/R\u00b2) "
                                           "= %1 kg, b = \u221a(J/m_eff) = %2 m with J = I + 2I2 + "
                                           "2a\u00b2(m + I1/R\u00b2) "
                                           "(B18); a = %3 m")
            .arg(num(d.mass), num(d.b), num(d.a));
    }
    return {};
}

// what every section reads: the solution, the state at t and the system
struct At {
    const Solution& s;
    double t;
    MotionSample m;
    const ControlState& c;
    const DerivedSystem& d;
    bool energy, pivot;
    double v;
};

// the system and the state at t
QString header(const At& at) {
    const auto& [s, t, m, c, d, energy, pivot, v] = at;
    QString h;
    h += QStringLiteral("<p>") + systemLine(s) + QStringLiteral("</p>");
    h += QCoreApplication::translate(
             "EquationsPanel",
             "<p>t = <b>%1 s</b>: s = %2 m, \u03c6 = %3 rad, \u03ba = %4 1/m; %5</p>")
             .arg(num(t), num(m.s), num(m.phi), num(m.kappa),
                  energy ? QCoreApplication::translate("EquationsPanel",
                                                       "constant energy, v_T = %1 m/s")
                               .arg(num(v))
                         : QCoreApplication::translate("EquationsPanel",
                                                       "constant speed, v_s = %1 m/s (App. C)")
                               .arg(num(v)));
    return h;
}

// Ψ on its branch, at a corner or backing up through a cusp
QString controlAngle(const At& at) {
    const auto& [s, t, m, c, d, energy, pivot, v] = at;
    QString h;
    h += section(QCoreApplication::translate("EquationsPanel", "Control angle"));
    if (pivot) {
        h += row(QStringLiteral("\u03a8"),
                 QCoreApplication::translate("EquationsPanel", "%1 (corner: b\u03ba \u2192 %2)")
                     .arg(c.psi < 1 ? QStringLiteral("0") : QStringLiteral("\u03c0"),
                          m.kappa > 0 ? QStringLiteral("+\u221e") : QStringLiteral("\u2212\u221e")),
                 c.psi, QStringLiteral("rad"),
                 QCoreApplication::translate("EquationsPanel",
                                             "pivot about P, docs/physics.md \u00a7"
                                             "3"));
    } else if (!(c.sdot > 0)) {
        h += row(QStringLiteral("\u03a8 = atan2(\u1e61, b\u03c6\u0307)"),
                 QStringLiteral("atan2(%1, %2 \u00b7 %3)")
                     .arg(num(c.sdot), operand(d.b), operand(c.phidot)),
                 c.psi, QStringLiteral("rad"),
                 QCoreApplication::translate("EquationsPanel",
                                             "at or after a cusp the sleigh backs up: \u03a8 "
                                             "leaves (0, \u03c0) continuously (docs/physics.md "
                                             "\u00a7"
                                             "3)"));
    } else {
        h += row(QStringLiteral("\u03a8 = atan2(1, b\u03ba)"),
                 QStringLiteral("atan2(1, %1 \u00b7 %2)").arg(operand(d.b), operand(m.kappa)),
                 c.psi, QStringLiteral("rad"),
                 QCoreApplication::translate(
                     "EquationsPanel",
                     "(45) tan \u03a8 = \u03c1/b on the branch \u03a8 \u2208 (0, \u03c0) "
                     "(erratum to (47))"));
    }
    return h;
}

// ṡ, φ̇, the time law and the energy, in the scene's speed mode
QString velocities(const At& at) {
    const auto& [s, t, m, c, d, energy, pivot, v] = at;
    QString h;
    h += section(QCoreApplication::translate("EquationsPanel", "Velocities and time law"));
    if (pivot) {
        h += row(QStringLiteral("\u1e61"), {}, c.sdot, QStringLiteral("m/s"),
                 QCoreApplication::translate("EquationsPanel", "turning in place"));
        h += row(QStringLiteral("\u03c6\u0307 = \u00b1v_T/b"),
                 QStringLiteral("\u00b1%1/%2").arg(operand(v), operand(d.b)), c.phidot,
                 QStringLiteral("rad/s"),
                 QCoreApplication::translate("EquationsPanel", "(35) with \u03a8 = 0 or \u03c0"));
    } else if (energy) {
        h += row(QStringLiteral("\u1e61 = v_T sin \u03a8"),
                 QStringLiteral("%1 \u00b7 sin %2").arg(operand(v), operand(c.psi)), c.sdot,
                 QStringLiteral("m/s"), QStringLiteral("(34)"));
        h += row(QStringLiteral("\u03c6\u0307 = (v_T/b) cos \u03a8 = \u03ba\u1e61"),
                 QStringLiteral("%1 \u00b7 %2").arg(operand(m.kappa), operand(c.sdot)), c.phidot,
                 QStringLiteral("rad/s"), QStringLiteral("(35)"));
        h += row(
            QStringLiteral("dt/ds = \u221a(1 + b\u00b2\u03ba\u00b2)/v_T = 1/|\u1e61|"),
            QStringLiteral("1/%1").arg(operand(std::fabs(c.sdot))), 1 / std::fabs(c.sdot),
            QStringLiteral("s/m"),
            QCoreApplication::translate(
                "EquationsPanel",
                "(51); (52)\u2013(53) corrected: 1/sin \u03a8 = \u221a(1 + b\u00b2\u03ba\u00b2)"));
    } else {
        h += row(QStringLiteral("\u1e61 = v_s"), num(v), c.sdot, QStringLiteral("m/s"),
                 QStringLiteral("(C17)\u2013(C18)"));
        h += row(QStringLiteral("\u03c6\u0307 = v_s\u03ba = (v_s/b) cot \u03a8"),
                 QStringLiteral("%1 \u00b7 %2").arg(operand(v), operand(m.kappa)), c.phidot,
                 QStringLiteral("rad/s"), QStringLiteral("(C16)"));
        h += row(QStringLiteral("v_T = v_s/sin \u03a8 = v_s\u221a(1 + b\u00b2\u03ba\u00b2)"),
                 QStringLiteral("%1/sin %2").arg(operand(v), operand(c.psi)), c.vT,
                 QStringLiteral("m/s"),
                 QCoreApplication::translate("EquationsPanel", "(C15): the energy varies"));
        h += row(QStringLiteral("dt/ds = 1/v_s"), QStringLiteral("1/%1").arg(operand(v)), 1 / v,
                 QStringLiteral("s/m"), QCoreApplication::translate("EquationsPanel", "t = s/v_s"));
    }
    h += row(QStringLiteral("T = (m/2)(\u1e61\u00b2 + b\u00b2\u03c6\u0307\u00b2)"),
             QStringLiteral("(%1/2)(%2\u00b2 + %3\u00b2\u00b7%4\u00b2)")
                 .arg(operand(d.mass), operand(c.sdot), operand(d.b), operand(c.phidot)),
             c.energy, QStringLiteral("J"),
             QCoreApplication::translate("EquationsPanel", "(49) with \u1e61\u00b2 (erratum)"));
    return h;
}

// χ, Ψ̇ and λ
QString multiplier(const At& at) {
    const auto& [s, t, m, c, d, energy, pivot, v] = at;
    QString h;
    h += section(
        QCoreApplication::translate("EquationsPanel", "Driving angle and control multiplier"));
    h += row(QStringLiteral("\u03c7 = \u03a8 \u2212 (a/b)\u03c6"),
             QStringLiteral("%1 \u2212 (%2/%3) \u00b7 %4")
                 .arg(operand(c.psi), operand(d.a), operand(d.b), operand(m.phi)),
             c.chi, QStringLiteral("rad"), QStringLiteral("(33)"));
    if (!pivot)
        h += row(
            QStringLiteral("\u03a8\u0307 = \u2212b\u03ba\u209b\u1e61/(1 + b\u00b2\u03ba\u00b2)"),
            {}, c.psidot, QStringLiteral("rad/s"),
            QCoreApplication::translate("EquationsPanel", "docs/physics.md \u00a7"
                                                          "2"));
    h += row(
        QStringLiteral("\u03bb = m b\u03c7\u0307 = m(b\u03a8\u0307 \u2212 a\u03c6\u0307)"),
        QStringLiteral("%1 (%2 \u00b7 %3 \u2212 %4 \u00b7 %5)")
            .arg(operand(d.mass), operand(d.b), operand(c.psidot), operand(d.a), operand(c.phidot)),
        c.lambda, QStringLiteral("kg m/s"), QStringLiteral("(25), (33)"));
    return h;
}

// the control force, the knife's reaction, the couple and their power
QString forces(const At& at) {
    const auto& [s, t, m, c, d, energy, pivot, v] = at;
    QString h;
    h += section(QCoreApplication::translate("EquationsPanel", "Forces on the body"));
    h += row(QStringLiteral("f_s = F_cs = m(s\u0308 \u2212 a\u03c6\u0307\u00b2)"),
             QStringLiteral("%1 (%2 \u2212 %3 \u00b7 %4\u00b2)")
                 .arg(operand(d.mass), operand(c.sddot), operand(d.a), operand(c.phidot)),
             c.forceAxial, QStringLiteral("N"),
             energy ? QCoreApplication::translate("EquationsPanel",
                                                  "= \u03bb\u03c6\u0307 (docs/physics.md \u00a7"
                                                  "2)")
                    : QCoreApplication::translate("EquationsPanel", "docs/physics.md \u00a7"
                                                                    "2"));
    if (d.translatingMass == d.mass)
        h += row(QStringLiteral("N = F_c\u03c6 = m(\u1e61\u03c6\u0307 + a\u03c6\u0308)"),
                 QStringLiteral("%1 (%2 \u00b7 %3 + %4 \u00b7 %5)")
                     .arg(operand(d.mass), operand(c.sdot), operand(c.phidot), operand(d.a),
                          operand(c.phiddot)),
                 c.knifeReaction, QStringLiteral("N"),
                 QCoreApplication::translate("EquationsPanel", "(69)\u2013(70), at P"));
    else // the lateral reaction moves only the mass that translates with P
        h += row(QStringLiteral("N = F_c\u03c6 = m_t \u1e61\u03c6\u0307 + m_eff a\u03c6\u0308"),
                 QStringLiteral("%1 \u00b7 %2 \u00b7 %3 + %4 \u00b7 %5 \u00b7 %6")
                     .arg(operand(d.translatingMass), operand(c.sdot), operand(c.phidot),
                          operand(d.mass), operand(d.a), operand(c.phiddot)),
                 c.knifeReaction, QStringLiteral("N"),
                 QCoreApplication::translate("EquationsPanel",
                                             "(69)\u2013(70), at P; m_t = %1 kg translates with "
                                             "P (the disk's m, the carriage's M + 2m)")
                     .arg(num(d.translatingMass)));
    h += row(
        QStringLiteral("\u03c4 = I\u03c6\u0308 + aN"),
        QStringLiteral("%1 \u00b7 %2 + %3 \u00b7 %4")
            .arg(operand(d.inertia()), operand(c.phiddot), operand(d.a), operand(c.knifeReaction)),
        c.controlCouple, QStringLiteral("N m"),
        energy
            ? QCoreApplication::translate(
                  "EquationsPanel",
                  "= \u2212\u03bb\u1e61: workless (S_c = I\u03c6\u0308, erratum to (66)\u2013(68))")
            : QCoreApplication::translate("EquationsPanel",
                                          "S_c = I\u03c6\u0308 (erratum to (66)\u2013(68))"));
    h += row(QCoreApplication::translate("EquationsPanel", "power f_s\u1e61 + \u03c4\u03c6\u0307"),
             QStringLiteral("%1 \u00b7 %2 + %3 \u00b7 %4")
                 .arg(operand(c.forceAxial), operand(c.sdot), operand(c.controlCouple),
                      operand(c.phidot)),
             c.forceAxial * c.sdot + c.controlCouple * c.phidot, QStringLiteral("W"),
             energy ? QCoreApplication::translate("EquationsPanel", "0: the control does no work")
                    : QCoreApplication::translate(
                          "EquationsPanel", "dT/dt = m b\u00b2\u03c6\u0307\u03c6\u0308 (App. C)"));
    return h;
}

// the free Lagrange–d'Alembert body's velocities and knife reaction
QString freeBody(const At& at) {
    const auto& [s, t, m, c, d, energy, pivot, v] = at;
    QString h;
    h += section(QCoreApplication::translate("EquationsPanel", "Free body (Lagrange\u2013"
                                                               "d'Alembert ghost)"));
    const FreeMotion::Constants k = s.freeMotion().constants();
    const FreeState& f = m.free;
    if (k.general) {
        h += row(QStringLiteral("\u1e61 = V tanh(kt + c)"),
                 QStringLiteral("%1 tanh(%2 \u00b7 %3 + %4)")
                     .arg(operand(k.v), operand(k.k), operand(t), operand(k.c)),
                 f.sdot, QStringLiteral("m/s"),
                 QCoreApplication::translate("EquationsPanel", "(D12)\u2013(D14) in closed form"));
        h += row(
            QStringLiteral("\u03c6\u0307 = \u03c3(V/b) sech(kt + c)"),
            QStringLiteral("%1 (%2/%3) sech(%4)")
                .arg(k.sigma > 0 ? QStringLiteral("+") : QStringLiteral("\u2212"), operand(k.v),
                     operand(d.b), num(k.k * t + k.c)),
            f.phidot, QStringLiteral("rad/s"),
            QCoreApplication::translate(
                "EquationsPanel",
                "V = \u221a(\u1e61\u2080\u00b2 + b\u00b2\u03c6\u0307\u2080\u00b2), k = aV/b\u00b2, "
                "c = atanh(\u1e61\u2080/V)"));
    } else {
        h += row(QStringLiteral("\u1e61"), {}, f.sdot, QStringLiteral("m/s"),
                 technicalModel(s.models().freeVelocity));
        h += row(QStringLiteral("\u03c6\u0307"), {}, f.phidot, QStringLiteral("rad/s"), {});
    }
    h += row(
        QStringLiteral("N = \u2212\u03bc = m(1 \u2212 a\u00b2/b\u00b2)\u1e61\u03c6\u0307"),
        QStringLiteral("%1 (1 \u2212 %2\u00b2/%3\u00b2) \u00b7 %4 \u00b7 %5")
            .arg(operand(d.mass), operand(d.a), operand(d.b), operand(f.sdot), operand(f.phidot)),
        freeBodyState(d, f).knifeReaction, QStringLiteral("N"), QStringLiteral("(D15)"));
    return h;
}

// the closed-loop body's feedback law at t (docs/physics.md §9), when the scene has a perturbation
QString feedbackLaw(const At& at) {
    const auto& [s, t, m, c, d, energy, pivot, v] = at;
    const PerturbedState fb = s.feedback()->at(t);
    const FeedbackLawValues& law = fb.law;
    const FeedbackLawValues& z = law;
    const PathPoint& p = law.closest.point;
    const Perturbation& spec = *s.scene().perturbation;
    const double rate = spec.feedbackRate;
    const double bc = spec.controllerB.value_or(d.b);
    QString h;
    h += section(QCoreApplication::translate("EquationsPanel", "Feedback law (closed loop)"));
    h += QCoreApplication::translate(
             "EquationsPanel",
             "<p>The feedback body against its closest path point: s_p = %1 m, \u03ba = %2 1/m, "
             "\u03ba\u2032 = %3 1/m\u00b2; feedback rate P = %4 1/m</p>")
             .arg(num(p.s), num(p.kappa), num(p.dkappa), num(rate));
    h += row(QStringLiteral("z\u2082 = e"), {}, z.z2, QStringLiteral("m"),
             QCoreApplication::translate("EquationsPanel",
                                         "lateral error, > 0 to the left of the path"));
    h += row(QStringLiteral("\u03b8 = \u03c6 \u2212 \u03c6_path(s_p)"),
             QStringLiteral("%1 \u2212 %2").arg(operand(fb.phi), operand(p.phi)), law.theta,
             QStringLiteral("rad"), QCoreApplication::translate("EquationsPanel", "heading error"));
    h += row(QStringLiteral("z\u2083 = (1 \u2212 \u03bae) tan \u03b8"),
             QStringLiteral("(1 \u2212 %1 \u00b7 %2) tan %3")
                 .arg(operand(p.kappa), operand(z.z2), operand(law.theta)),
             z.z3, {}, QCoreApplication::translate("EquationsPanel", "= dz\u2082/ds_p"));
    h += row(
        QStringLiteral("z\u2084 = \u2212\u03ba\u2032e tan \u03b8 \u2212 "
                       "\u03ba(1 \u2212 \u03bae)(tan\u00b2\u03b8 + sec\u00b2\u03b8) + "
                       "\u03ba_b(1 \u2212 \u03bae)\u00b2 sec\u00b3\u03b8"),
        QStringLiteral("\u2026 with \u03ba_b = \u03c6\u0307/\u1e61 = %1").arg(num(law.kappaBody)),
        z.z4, QStringLiteral("1/m"),
        QCoreApplication::translate("EquationsPanel", "= dz\u2083/ds_p"));
    h += row(QStringLiteral("u = \u2212P\u00b3z\u2082 \u2212 3P\u00b2z\u2083 \u2212 3Pz\u2084"),
             QStringLiteral("\u2212%1\u00b3 \u00b7 %2 \u2212 3 \u00b7 %1\u00b2 \u00b7 %3 "
                            "\u2212 3 \u00b7 %1 \u00b7 %4")
                 .arg(operand(rate), operand(z.z2), operand(z.z3), operand(z.z4)),
             law.u, QStringLiteral("1/m\u00b2"),
             QCoreApplication::translate(
                 "EquationsPanel",
                 "a triple pole at \u2212P in path length: e\u2034 + 3Pe\u2033 + 3P\u00b2"
                 "e\u2032 + P\u00b3"
                 "e = 0"));
    h += row(
        QStringLiteral("\u03ba_b\u2032 = (u \u2212 F)/G"),
        QStringLiteral("(%1 \u2212 %2)/%3").arg(operand(law.u), operand(z.drift), operand(z.gain)),
        law.curvatureRate, QStringLiteral("1/m\u00b2"),
        QCoreApplication::translate("EquationsPanel",
                                    "dz\u2084/ds_p = G\u03ba_b\u2032 + F, G = (1 \u2212 \u03ba"
                                    "e)\u00b2 "
                                    "sec\u00b3\u03b8"));
    const QString bound =
        law.saturated ? QCoreApplication::translate("EquationsPanel",
                                                    "; held at the limit |\u03a8\u0307| \u2264 %1 "
                                                    "rad/s")
                            .arg(num(spec.feedbackLimit.value_or(0)))
                      : QString();
    if (bc == d.b)
        h += row(QStringLiteral("\u03a8\u0307 = \u2212b \u1e61_p \u03ba_b\u2032/(1 + "
                                "b\u00b2\u03ba_b\u00b2)"),
                 QStringLiteral("\u2212%1 \u00b7 %2 \u00b7 %3/(1 + %1\u00b2 \u00b7 %4\u00b2)")
                     .arg(operand(d.b), operand(law.sdotPath), operand(law.curvatureRate),
                          operand(law.kappaBody)),
                 fb.psidot, QStringLiteral("rad/s"),
                 QCoreApplication::translate("EquationsPanel", "from \u03ba_b = cot \u03a8/b") +
                     bound);
    else
        h += row(QStringLiteral("\u03a8\u0307 = \u2212(b_c/b) b_c \u1e61_p "
                                "\u03ba_b\u2032/(1 + b_c\u00b2\u03ba_b\u00b2)"),
                 QStringLiteral("\u2212(%1/%2) %1 \u00b7 %3 \u00b7 %4/(1 + %1\u00b2 \u00b7 "
                                "%5\u00b2)")
                     .arg(operand(bc), operand(d.b), operand(law.sdotPath),
                          operand(law.curvatureRate), operand(law.kappaBody)),
                 fb.psidot, QStringLiteral("rad/s"),
                 QCoreApplication::translate("EquationsPanel",
                                             "the controller's b_c = %1 m differs from the "
                                             "plant's")
                         .arg(num(bc)) +
                     bound);
    h += row(QStringLiteral("\u03bb_fb = m_eff(b\u03a8\u0307 \u2212 a\u03c6\u0307)"),
             QStringLiteral("%1 (%2 \u00b7 %3 \u2212 %4 \u00b7 %5)")
                 .arg(operand(d.mass), operand(d.b), operand(fb.psidot), operand(d.a),
                      operand(fb.phidot)),
             fb.lambda, QStringLiteral("kg m/s"),
             QCoreApplication::translate("EquationsPanel",
                                         "workless: the energy stays (m_eff/2)(\u1e61\u00b2 + "
                                         "b\u00b2\u03c6\u0307\u00b2) = %1 J")
                 .arg(num(fb.energy)));
    return h;
}

} // namespace

QString planHtml(const PlanRequest& request, const PlannedGeodesic& g, int index, int count,
                 double t) {
    QString family;
    switch (g.family) {
    case GeodesicFamily::Rest:
        family = QCoreApplication::translate("EquationsPanel", "at rest (the target is the start)");
        break;
    case GeodesicFamily::Pivot:
        family = QCoreApplication::translate("EquationsPanel",
                                             "pivoting about P (\u03a8 \u2261 0 or \u03c0)");
        break;
    case GeodesicFamily::Line:
        family = QCoreApplication::translate("EquationsPanel",
                                             "the straight line (\u03a8 \u2261 \u00b1\u03c0/2)");
        break;
    case GeodesicFamily::Libration:
        family = QCoreApplication::translate("EquationsPanel", "libration (k &lt; 1)");
        break;
    case GeodesicFamily::Rotation:
        family = QCoreApplication::translate("EquationsPanel", "rotation (k &gt; 1)");
        break;
    case GeodesicFamily::Separatrix:
        family = QCoreApplication::translate("EquationsPanel", "separatrix (k = 1)");
        break;
    }
    const DerivedSystem& d = request.system;
    const double v = request.vT;
    const VakonomicState now =
        VakonomicMotion(d, plannedStart(request, g)).at(std::clamp(t, 0.0, g.t));
    QString h = section(QCoreApplication::translate("EquationsPanel", "Plan: motion %1 of %2, %3")
                            .arg(index + 1)
                            .arg(count)
                            .arg(family));
    h += row(QStringLiteral(
                 "k\u00b2 = sin\u00b2\u03a8\u2080 + (b\u03a8\u0307\u2080/v<sub>T</sub>)\u00b2"),
             QStringLiteral("sin\u00b2%1 + (%2 \u00b7 %3/%4)\u00b2")
                 .arg(operand(g.psi0), operand(d.b), operand(g.psidot0), operand(v)),
             g.modulus * g.modulus, QString(),
             QCoreApplication::translate("EquationsPanel",
                                         "the pendulum's modulus, docs/physics.md \u00a7"
                                         "10"));
    h += row(QStringLiteral("\u03a8\u2080"), QString(), g.psi0, QStringLiteral("rad"),
             QCoreApplication::translate("EquationsPanel",
                                         "\u03a8(0) = atan2(\u1e61, b\u03c6\u0307) at the start"));
    h += row(QStringLiteral("\u03bb(0) = m(b\u03a8\u0307\u2080 \u2212 a v<sub>T</sub> cos "
                            "\u03a8\u2080/b)"),
             QStringLiteral("%1 \u00b7 (%2 \u00b7 %3 \u2212 %4 \u00b7 %5 \u00b7 cos %6/%2)")
                 .arg(operand(d.mass), operand(d.b), operand(g.psidot0), operand(d.a), operand(v),
                      operand(g.psi0)),
             g.lambda0, QStringLiteral("kg m/s"),
             QCoreApplication::translate("EquationsPanel", "the one free constant: the control"));
    h +=
        row(QStringLiteral("t"), QString(), g.t, QStringLiteral("s"),
            g.optimal ? QCoreApplication::translate(
                            "EquationsPanel", "arrival, the least time (certified by the cut time)")
                      : QCoreApplication::translate("EquationsPanel", "arrival"));
    h += row(QCoreApplication::translate("EquationsPanel", "cut time"), QString(), g.cutTime,
             QStringLiteral("s"),
             QCoreApplication::translate("EquationsPanel",
                                         "optimal up to here: the first Maxwell time"));
    h +=
        row(QStringLiteral("\u03a8(t)"), QString(), now.psi, QStringLiteral("rad"),
            QCoreApplication::translate("EquationsPanel", "along the motion now, t clamped to it"));
    h += row(QStringLiteral("\u03bb(t)"), QString(), now.lambda, QStringLiteral("kg m/s"),
             QCoreApplication::translate("EquationsPanel", "along the motion now"));
    return h;
}

QString equationsHtml(const Solution& s, double t) {
    t = std::clamp(t, 0.0, s.tEnd());
    const MotionSample m = s.at(t);
    const At at{s,
                t,
                m,
                m.control,
                s.system(),
                s.params().mode == SpeedMode::Energy,
                std::isinf(m.kappa),
                s.params().speed};
    QString h = QStringLiteral("<html><body>") + header(at);
    for (QString (*part)(const At&) : {controlAngle, velocities, multiplier, forces, freeBody})
        h += part(at);
    if (s.perturbed())
        h += feedbackLaw(at);
    return h + QStringLiteral("</body></html>");
}

} // namespace chaplygin::ui
