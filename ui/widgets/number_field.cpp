#include "widgets/number_field.h"

#include "common/input_error.h"
#include "paths/expression.h"

#include <QKeyEvent>
#include <QLineEdit>
#include <QStyle>
#include <QStyleOptionSpinBox>

#include <charconv>
#include <cmath>
#include <cstdlib>

namespace chaplygin::ui {

namespace {

// 10^k exactly for the powers a double holds exactly, correctly rounded otherwise
double powerOfTen(int k) {
    static constexpr double exact[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                       1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                       1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
    return k >= 0 && k <= 22 ? exact[k] : std::pow(10.0, k);
}

// n * 10^k with one rounding: n / 10^-k for a step below one, so 12 steps of 0.1 are 1.2
double scaled(double n, int k) {
    return k >= 0 ? n * powerOfTen(k) : (k >= -22 ? n / powerOfTen(-k) : n * powerOfTen(k));
}

// the exponent of |v|'s leading decimal digit
int decadeOf(double magnitude) {
    int d = int(std::floor(std::log10(magnitude)));
    if (powerOfTen(d) > magnitude)
        --d;
    else if (powerOfTen(d + 1) <= magnitude)
        ++d;
    return d;
}

} // namespace

NumberField::NumberField(const QString& name, QWidget* parent)
    : QAbstractSpinBox(parent), m_name(name) {
    setKeyboardTracking(false);
    setAccelerated(true);
    setAccessibleName(name);
    showValue();
}

QString NumberField::formatted(double v) {
    char buffer[400];
    const double magnitude = std::abs(v);
    const bool plain = magnitude == 0 || (magnitude >= 1e-4 && magnitude < 1e15);
    const auto result =
        std::to_chars(buffer, buffer + sizeof buffer, v,
                      plain ? std::chars_format::fixed : std::chars_format::scientific);
    return QString::fromLatin1(buffer, int(result.ptr - buffer));
}

double NumberField::stepped(double v, int direction, double zeroStep, bool integers) {
    const double magnitude = std::abs(v);
    if (magnitude == 0 || !std::isfinite(v))
        return direction * (integers ? std::max(1.0, std::round(zeroStep)) : zeroStep);
    int k = decadeOf(magnitude) - 1; // the step: a tenth of the leading digit's place
    const bool towardsZero = direction * v < 0;
    if (towardsZero && powerOfTen(k + 1) == magnitude)
        --k; // 1 steps down to 0.99, not to 0.9, which would step up to 0.91
    if (integers && k < 0)
        k = 0;
    const double position = k >= 0 ? v / powerOfTen(k) : v * powerOfTen(-k);
    const double nearest = std::round(position);
    // on the grid: the next point; between points: the next one in that direction
    const bool onGrid = std::abs(position - nearest) <= 1e-9 * std::max(1.0, std::abs(nearest));
    const double n = onGrid ? nearest + direction
                            : (direction > 0 ? std::floor(position) + 1 : std::ceil(position) - 1);
    return scaled(n, k);
}

void NumberField::setValue(double value) {
    const bool changed = value != m_value || std::signbit(value) != std::signbit(m_value);
    m_value = value;
    setMessage({});
    showValue();
    if (changed)
        emit valueChanged(value);
}

void NumberField::setName(const QString& name) {
    m_name = name;
    setAccessibleName(name);
}

void NumberField::setUnit(const QString& unit) {
    m_unit = unit;
    showValue();
    updateGeometry();
}

void NumberField::setMinimum(double lo, bool open) {
    m_min = lo;
    m_minOpen = open;
}

void NumberField::setMaximum(double hi, bool open) {
    m_max = hi;
    m_maxOpen = open;
}

void NumberField::setIntegers(bool integers) {
    m_integers = integers;
}

QString NumberField::withUnit(double v) const {
    if (m_unit.isEmpty())
        return formatted(v);
    // a degree sign follows its number (35°); other units after a space (1.5 kg)
    return m_unit.startsWith(QChar(0x00b0)) ? formatted(v) + m_unit
                                            : formatted(v) + QLatin1Char(' ') + m_unit;
}

void NumberField::showValue() {
    lineEdit()->setText(withUnit(m_value));
    if (!hasFocus())
        lineEdit()->setCursorPosition(0); // a long value too narrow to show shows its first digits
}

QString NumberField::refusalOf(double v) const {
    auto bound = [this](double b) { return withUnit(b); };
    if (m_min && (m_minOpen ? !(v > *m_min) : !(v >= *m_min)))
        return m_minOpen ? tr("%1 must be greater than %2").arg(m_name, bound(*m_min))
                         : tr("%1 must be at least %2").arg(m_name, bound(*m_min));
    if (m_max && (m_maxOpen ? !(v < *m_max) : !(v <= *m_max)))
        return m_maxOpen ? tr("%1 must be less than %2").arg(m_name, bound(*m_max))
                         : tr("%1 must be at most %2").arg(m_name, bound(*m_max));
    if (m_integers && v != std::round(v))
        return tr("%1 must be a whole number").arg(m_name);
    return m_check ? m_check(v) : QString();
}

void NumberField::setMessage(const QString& message) {
    if (message == m_message)
        return;
    m_message = message;
    const bool refused = !message.isEmpty();
    setProperty("invalid", refused);
    setStyleSheet(refused ? QStringLiteral("QAbstractSpinBox { border: 2px solid #b00020; "
                                           "background: #fdecee; }")
                          : QString());
    setAccessibleDescription(refused ? tr("invalid: %1").arg(message) : QString());
    emit messageChanged(message);
}

bool NumberField::commitText() {
    QString text = lineEdit()->text().trimmed();
    if (m_message.isEmpty() && text == withUnit(m_value))
        return true; // nothing typed
    if (!m_unit.isEmpty() && text.endsWith(m_unit))
        text.chop(m_unit.size());
    double v = 0;
    try {
        v = evaluateNumber(text.trimmed().toStdString(), m_name.toStdString());
    } catch (const InputError& e) {
        setMessage(QString::fromStdString(e.what()));
        return false;
    }
    if (const QString refusal = refusalOf(v); !refusal.isEmpty()) {
        setMessage(refusal);
        return false;
    }
    setMessage({});
    const bool changed = v != m_value || std::signbit(v) != std::signbit(m_value);
    m_value = v;
    showValue();
    if (changed)
        emit valueChanged(v);
    return true;
}

QValidator::State NumberField::validate(QString&, int&) const {
    return QValidator::Acceptable; // any text while typing: it is read on Enter or on leaving
}

void NumberField::stepBy(int steps) {
    if (!commitText())
        return;
    const int direction = steps > 0 ? 1 : -1;
    double v = m_value;
    for (int i = 0; i < std::abs(steps); ++i) {
        const double next = stepped(v, direction, m_zeroStep, m_integers);
        if (!refusalOf(next).isEmpty())
            break;
        v = next;
    }
    if (v == m_value)
        return;
    m_value = v;
    showValue();
    emit valueChanged(v);
}

QAbstractSpinBox::StepEnabled NumberField::stepEnabled() const {
    if (isReadOnly())
        return StepNone;
    StepEnabled enabled = StepNone;
    if (refusalOf(stepped(m_value, 1, m_zeroStep, m_integers)).isEmpty())
        enabled |= StepUpEnabled;
    if (refusalOf(stepped(m_value, -1, m_zeroStep, m_integers)).isEmpty())
        enabled |= StepDownEnabled;
    return enabled;
}

void NumberField::keyPressEvent(QKeyEvent* event) {
    const bool enter = event->key() == Qt::Key_Return || event->key() == Qt::Key_Enter;
    if (enter && !commitText()) {
        event->accept(); // a refused value keeps the keyboard, and applies nothing
        return;
    }
    QAbstractSpinBox::keyPressEvent(event); // Enter goes on to the parent (a dialog's default)
}

void NumberField::focusOutEvent(QFocusEvent* event) {
    commitText();
    QAbstractSpinBox::focusOutEvent(event);
}

// the spin box's frame and arrows around room for `sample` (QAbstractSpinBox's own hints know no
// value of this field)
QSize NumberField::sizeFor(const QString& sample) const {
    ensurePolished();
    QStyleOptionSpinBox option;
    initStyleOption(&option);
    const QSize content(fontMetrics().horizontalAdvance(sample) + 2,
                        lineEdit()->minimumSizeHint().height());
    return style()->sizeFromContents(QStyle::CT_SpinBox, &option, content, this);
}

QSize NumberField::sizeHint() const {
    return sizeFor(withUnit(-12.345)); // a longer value scrolls in the field until it grows
}

QSize NumberField::minimumSizeHint() const {
    return sizeFor(withUnit(0.5)); // a narrow dock scrolls a longer value
}

} // namespace chaplygin::ui
