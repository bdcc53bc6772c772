// The Equations dock's arithmetic read as printed: each substituted line, evaluated by hand with
// the numbers it shows, gives the value it shows (as far as the shown digits carry). A negative
// factor stands in parentheses: a sign right after an operator is refused, as a reader would
// stumble on it.
#include "lab/gallery.h"
#include "panels/equations_html.h"
#include "scene/perturbation.h"
#include "scene/presets.h"
#include "scene/solution.h"
#include "systems/system.h"

#include <QRegularExpression>
#include <QtTest>

#include <cmath>
#include <functional>
#include <memory>
#include <stdexcept>
#include <vector>

using namespace chaplygin;

namespace {

// A formula as printed, parsed into a tree whose leaves are the printed numbers, each with half a
// unit of its last shown digit (4 significant digits, as the dock prints them)
struct Node {
    char op = 'n'; // n number, + - * / ^ (power), f (function), u (negation)
    double value = 0, halfUnit = 0;
    QString function;
    std::vector<std::unique_ptr<Node>> args;
};

class Reader {
  public:
    explicit Reader(const QString& text) : m_text(text) {}

    std::unique_ptr<Node> whole() {
        auto e = expression();
        skipSpace();
        if (m_pos != m_text.size())
            fail("unexpected text");
        return e;
    }

  private:
    [[noreturn]] void fail(const char* what) const {
        throw std::runtime_error(QStringLiteral("%1 at %2 in '%3'")
                                     .arg(QString::fromUtf8(what))
                                     .arg(m_pos)
                                     .arg(m_text)
                                     .toStdString());
    }
    void skipSpace() {
        while (m_pos < m_text.size() && m_text[m_pos] == u' ')
            ++m_pos;
    }
    QChar peek() {
        skipSpace();
        return m_pos < m_text.size() ? m_text[m_pos] : QChar();
    }
    static bool isMinus(QChar c) { return c == u'\u2212' || c == u'-'; }
    static std::unique_ptr<Node> binary(char op, std::unique_ptr<Node> a, std::unique_ptr<Node> b) {
        auto n = std::make_unique<Node>();
        n->op = op;
        n->args.push_back(std::move(a));
        n->args.push_back(std::move(b));
        return n;
    }

    // a sum; a sign only at its start (the start of the line, after "(" or ",")
    std::unique_ptr<Node> expression() {
        bool negate = false;
        if (isMinus(peek()) || peek() == u'+') {
            negate = isMinus(peek());
            ++m_pos;
        }
        auto e = product();
        if (negate) {
            auto n = std::make_unique<Node>();
            n->op = 'u';
            n->args.push_back(std::move(e));
            e = std::move(n);
        }
        while (isMinus(peek()) || peek() == u'+') {
            const char op = isMinus(peek()) ? '-' : '+';
            ++m_pos;
            e = binary(op, std::move(e), product());
        }
        return e;
    }
    bool startsFactor() {
        const QChar c = peek();
        return c.isDigit() || c == u'(' || c.isLetter() || c == u'\u221a';
    }
    // factors joined by "·", "/" or nothing (1.6 (0.5 + 1))
    std::unique_ptr<Node> product() {
        auto e = power();
        for (;;) {
            if (peek() == u'\u00b7' || peek() == u'/') {
                const char op = peek() == u'/' ? '/' : '*';
                ++m_pos;
                e = binary(op, std::move(e), power());
            } else if (startsFactor()) {
                e = binary('*', std::move(e), power());
            } else {
                return e;
            }
        }
    }
    std::unique_ptr<Node> power() {
        auto e = primary();
        while (peek() == u'\u00b2' || peek() == u'\u00b3') {
            auto exponent = std::make_unique<Node>();
            exponent->value = peek() == u'\u00b2' ? 2 : 3;
            ++m_pos;
            e = binary('^', std::move(e), std::move(exponent));
        }
        return e;
    }
    std::unique_ptr<Node> primary() {
        const QChar c = peek();
        if (isMinus(c) || c == u'+')
            fail("a sign after an operator (a negative factor needs parentheses)");
        if (c == u'(') {
            ++m_pos;
            auto e = expression();
            if (peek() != u')')
                fail("missing ')'");
            ++m_pos;
            return e;
        }
        if (c == u'\u221a') {
            ++m_pos;
            auto n = std::make_unique<Node>();
            n->op = 'f';
            n->function = QStringLiteral("sqrt");
            n->args.push_back(power());
            return n;
        }
        if (c.isLetter()) {
            auto n = std::make_unique<Node>();
            n->op = 'f';
            while (m_pos < m_text.size() && m_text[m_pos].isLetterOrNumber())
                n->function += m_text[m_pos++];
            if (peek() == u'(') { // f(a) or atan2(a, b)
                ++m_pos;
                n->args.push_back(expression());
                while (peek() == u',') {
                    ++m_pos;
                    n->args.push_back(expression());
                }
                if (peek() != u')')
                    fail("missing ')' after the arguments");
                ++m_pos;
            } else { // sin 0.3
                n->args.push_back(power());
            }
            return n;
        }
        static const QRegularExpression number(QStringLiteral("\\G\\d+(\\.\\d+)?(e[-+]\\d+)?"));
        const auto match = number.match(m_text, m_pos);
        if (!match.hasMatch())
            fail("expected a number");
        auto n = std::make_unique<Node>();
        n->value = match.captured().toDouble();
        // 4 significant digits: half a unit of the fourth
        n->halfUnit =
            n->value == 0 ? 0 : 0.5 * std::pow(10.0, std::floor(std::log10(n->value)) - 3);
        m_pos += match.capturedLength();
        return n;
    }

    QString m_text;
    qsizetype m_pos = 0;
};

double evaluate(const Node& n) {
    auto arg = [&](std::size_t i) { return evaluate(*n.args.at(i)); };
    switch (n.op) {
    case 'n':
        return n.value;
    case 'u':
        return -arg(0);
    case '+':
        return arg(0) + arg(1);
    case '-':
        return arg(0) - arg(1);
    case '*':
        return arg(0) * arg(1);
    case '/':
        return arg(0) / arg(1);
    case '^':
        return std::pow(arg(0), arg(1));
    }
    const QString& f = n.function;
    if (f == QLatin1String("atan2") && n.args.size() == 2)
        return std::atan2(arg(0), arg(1));
    if (n.args.size() != 1)
        throw std::runtime_error("bad arguments to " + f.toStdString());
    const double x = arg(0);
    if (f == QLatin1String("sin"))
        return std::sin(x);
    if (f == QLatin1String("cos"))
        return std::cos(x);
    if (f == QLatin1String("tan"))
        return std::tan(x);
    if (f == QLatin1String("tanh"))
        return std::tanh(x);
    if (f == QLatin1String("sech"))
        return 1 / std::cosh(x);
    if (f == QLatin1String("sqrt"))
        return std::sqrt(x);
    throw std::runtime_error("unknown function " + f.toStdString());
}

void leaves(Node& n, std::vector<Node*>& out) {
    if (n.op == 'n' && n.halfUnit > 0)
        out.push_back(&n);
    for (auto& a : n.args)
        leaves(*a, out);
}

// A value as the dock prints it: 4 significant digits, U+2212 for minus
double shownValue(QString text) {
    text.replace(u'\u2212', u'-');
    bool ok = false;
    const double v = text.toDouble(&ok);
    if (!ok)
        throw std::runtime_error("not a number: " + text.toStdString());
    return v;
}

struct Checked {
    int lines = 0, negativeFactors = 0;
};

// every substituted line of the page evaluated as printed against its shown value; the failures
// as text
QString checkPage(const QString& html, Checked& checked) {
    static const QRegularExpression paragraph(
        QStringLiteral("<p style='margin: 1px 0 5px 0'>(.*?) <b>= ([^<]*)</b>"));
    QString failures;
    for (auto it = paragraph.globalMatch(html); it.hasNext();) {
        const auto match = it.next();
        const QString formula = match.captured(1);
        const QString shown = match.captured(2);
        const qsizetype eq = formula.lastIndexOf(QStringLiteral(" = "));
        // a line with no substitution, an infinite value, or a side definition ("\u2026 with")
        if (eq < 0 || shown.contains(u'\u221e') || formula.contains(u'\u2026'))
            continue;
        const QString substituted = formula.mid(eq + 3);
        // symbols, an ellipsis, a "±" or words: not arithmetic
        static const QRegularExpression words(
            QStringLiteral("[^\\d\\s.e+\\-\u2212\u00b7/()\u00b2\u00b3\u221a,]"));
        QString bare = substituted;
        for (const char* f : {"atan2", "tanh", "sech", "sin", "cos", "tan"})
            bare.remove(QString::fromLatin1(f));
        if (bare.contains(words) || !bare.contains(QRegularExpression(QStringLiteral("\\d"))))
            continue;
        try {
            auto tree = Reader(substituted).whole();
            const double value = evaluate(*tree), target = shownValue(shown);
            // the rounding of each shown number carried to the result, and the result's own
            std::vector<Node*> numbers;
            leaves(*tree, numbers);
            double carried = 0;
            for (Node* n : numbers) {
                const double v = n->value;
                n->value = v + n->halfUnit;
                const double up = evaluate(*tree);
                n->value = v - n->halfUnit;
                const double down = evaluate(*tree);
                n->value = v;
                carried += std::max(std::fabs(up - value), std::fabs(down - value));
            }
            const double own =
                target == 0 ? 5e-13
                            : 0.5 * std::pow(10.0, std::floor(std::log10(std::fabs(target))) - 3);
            if (!(std::fabs(value - target) <= 1.01 * carried + own + 1e-15))
                failures += QStringLiteral("'%1' evaluates to %2, shown %3 (allowed %4)\n")
                                .arg(substituted)
                                .arg(value, 0, 'g', 8)
                                .arg(shown)
                                .arg(carried + own, 0, 'g', 3);
            ++checked.lines;
            checked.negativeFactors += substituted.count(QStringLiteral("(\u2212"));
        } catch (const std::exception& e) {
            failures += QString::fromStdString(e.what()) + u'\n';
        }
    }
    return failures;
}

Scene withPerturbation(Scene s) {
    Perturbation p;
    setPerturbationField(p, "dy", 0.2);
    setPerturbationField(p, "dpsi", -0.3);
    s.perturbation = p;
    return s;
}

} // namespace

class TestEquationsArithmetic : public QObject {
    Q_OBJECT

  private slots:
    void readerRefusesASignAfterAnOperator();
    void everyLineEvaluatesAsPrinted_data();
    void everyLineEvaluatesAsPrinted();
};

// the check itself: the printing the dock used to do is refused, the parenthesised one evaluates
void TestEquationsArithmetic::readerRefusesASignAfterAnOperator() {
    QVERIFY_THROWS_EXCEPTION(std::runtime_error,
                             Reader(QStringLiteral("1.6 \u00b7 \u22120.8376")).whole());
    QVERIFY_THROWS_EXCEPTION(
        std::runtime_error,
        Reader(QStringLiteral("(1/2)(0.598\u00b2 + 1.6\u00b2\u00b7\u22120.5009\u00b2)")).whole());
    QCOMPARE(evaluate(*Reader(QStringLiteral("(1/2)(0.598\u00b2 + 1.6\u00b2\u00b7(\u22120.5009)"
                                             "\u00b2)"))
                           .whole()),
             0.5 * (0.598 * 0.598 + 1.6 * 1.6 * 0.5009 * 0.5009));
    QCOMPARE(evaluate(*Reader(QStringLiteral("\u22122 \u00b7 atan2(1, 0.5 \u00b7 (\u22121)) + "
                                             "1/sin 0.5 + 3 tanh(0.1 \u00b7 2 + (\u22120.3))"))
                           .whole()),
             -2 * std::atan2(1, -0.5) + 1 / std::sin(0.5) + 3 * std::tanh(0.2 - 0.3));
    // a page whose line is wrong is caught
    Checked checked;
    QVERIFY(
        !checkPage(QStringLiteral("<p style='margin: 1px 0 5px 0'>x = 1.5 \u00b7 2 <b>= 3.1</b>"),
                   checked)
             .isEmpty());
}

void TestEquationsArithmetic::everyLineEvaluatesAsPrinted_data() {
    QTest::addColumn<QString>("name");
    QTest::addColumn<double>("fraction"); // of the duration
    auto add = [](const char* name, std::initializer_list<double> fractions) {
        for (double f : fractions)
            QTest::newRow(qPrintable(QStringLiteral("%1 at %2").arg(QLatin1String(name)).arg(f)))
                << QString::fromLatin1(name) << f;
    };
    add("sinusoid", {0.0, 0.13, 0.37, 0.61, 0.9});
    add("catenary", {0.2, 0.7});
    add("circle", {0.5});
    add("line", {0.3});
    add("sinusoid speed", {0.21, 0.66});
    add("sinusoid disk", {0.4});
    add("sinusoid carriage", {0.8});
    add("sinusoid perturbed", {0.1, 0.45, 0.85});
    add("cusp", {0.25, 0.75});
    add("corner-pivot", {0.2, 0.5});
}

void TestEquationsArithmetic::everyLineEvaluatesAsPrinted() {
    QFETCH(QString, name);
    QFETCH(double, fraction);
    Scene scene;
    const std::string id = name.toStdString();
    if (id == "cusp" || id == "corner-pivot") {
        scene = galleryEntry(id).scene;
    } else {
        scene = presetScene(id.substr(0, id.find(' ')));
        if (id.ends_with(" speed")) {
            scene.mode = SpeedMode::Speed;
            scene.speed = 0.8;
        } else if (id.ends_with(" disk")) {
            scene.system.kind = SystemKind::Disk;
            scene.system.params = defaultSystemParams(SystemKind::Disk);
        } else if (id.ends_with(" carriage")) {
            scene.system.kind = SystemKind::Carriage;
            scene.system.params = defaultSystemParams(SystemKind::Carriage);
        } else if (id.ends_with(" perturbed")) {
            scene = withPerturbation(scene);
        }
    }
    const Solution solution = Solution::compute(scene);
    const double t = fraction * solution.tEnd();
    Checked checked;
    const QString failures = checkPage(ui::equationsHtml(solution, t), checked);
    QVERIFY2(failures.isEmpty(), qPrintable(failures));
    QVERIFY2(checked.lines >= 8, qPrintable(QString::number(checked.lines)));
    if (id == "cusp" && fraction > 0.5) // backing up: the negative speed in every product
        QVERIFY(checked.negativeFactors >= 5);
    qDebug("%s at t = %g: %d lines, %d negative factors", qPrintable(name), t, checked.lines,
           checked.negativeFactors);
}

QTEST_GUILESS_MAIN(TestEquationsArithmetic)
#include "test_equations_arithmetic.moc"
