#pragma once
#include <QAbstractSpinBox>
#include <QString>

#include <functional>
#include <optional>

namespace chaplygin::ui {

/// A number field: it takes the program's expression syntax ("2*pi", "1e6", "sqrt(2)",
/// evaluated by the core's evaluateNumber) and keeps the full double. It shows the shortest text
/// that reads back as the same double, so showing never changes the value. A value outside the
/// field's domain is refused with a message naming the field and the bound (messageChanged), the
/// field marked and its value kept; the arrows, the keys Up and Down and the wheel step by round
/// amounts of the value's magnitude (1, 1.1, 1.2; 10, 11).
class NumberField : public QAbstractSpinBox {
    Q_OBJECT
  public:
    /// name: what messages call the field ("m", "v_T", "x from").
    explicit NumberField(const QString& name, QWidget* parent = nullptr);

    double value() const { return m_value; }
    /// Sets and shows a value (emitting valueChanged when it differs, as QDoubleSpinBox does) and
    /// clears a refusal. A value set so is not checked against the domain.
    void setValue(double value);
    /// The unit shown after the number (a typed number may omit it).
    void setUnit(const QString& unit);
    QString unit() const { return m_unit; }
    /// The domain: values below lo (at lo too when open) are refused.
    void setMinimum(double lo, bool open = false);
    void setMaximum(double hi, bool open = false);
    /// A further rule of the domain (the core's check of a field): the message refusing a value,
    /// or empty.
    void setCheck(std::function<QString(double)> check) { m_check = std::move(check); }
    /// Whole numbers only.
    void setIntegers(bool integers);
    /// The step from 0, where the value has no magnitude.
    void setZeroStep(double step) { m_zeroStep = step; }
    QString name() const { return m_name; }
    void setName(const QString& name);
    /// The refusal shown, or empty.
    QString message() const { return m_message; }

    /// The shortest text that reads back as v: plain decimals from 1e-4 to 1e9, otherwise
    /// scientific ("1e-05").
    static QString formatted(double v);
    /// One step from v towards `direction` (+1 or -1): the next multiple of a tenth of v's
    /// decade (the finer decade below when v is a power of ten and the step goes towards 0).
    static double stepped(double v, int direction, double zeroStep, bool integers);

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

  signals:
    /// A new value: typed (read on Enter or on leaving the field), stepped, or set.
    void valueChanged(double value);
    /// A refusal, or empty when none stands.
    void messageChanged(const QString& message);

  protected:
    QValidator::State validate(QString& input, int& pos) const override;
    void stepBy(int steps) override;
    StepEnabled stepEnabled() const override;
    void keyPressEvent(QKeyEvent* event) override;
    void focusOutEvent(QFocusEvent* event) override;

  private:
    /// Reads the typed text; true when a new value or nothing new was typed, false on a refusal.
    bool commitText();
    /// The refusal of v, or empty when v lies in the domain.
    QString refusalOf(double v) const;
    void showValue();
    void setMessage(const QString& message);
    QString withUnit(double v) const;
    QSize sizeFor(const QString& sample) const;

    QString m_name;
    QString m_unit;
    double m_value = 0;
    std::optional<double> m_min, m_max;
    bool m_minOpen = false, m_maxOpen = false;
    bool m_integers = false;
    double m_zeroStep = 0.1;
    std::function<QString(double)> m_check;
    QString m_message;
};

} // namespace chaplygin::ui
