#include "shell/enter_to_canvas.h"

#include <QAbstractSpinBox>
#include <QApplication>
#include <QKeyEvent>
#include <QLineEdit>
#include <QPointer>
#include <QTimer>
#include <QWidget>

namespace chaplygin::ui {

EnterToCanvas::EnterToCanvas(QWidget* window, QWidget* canvas)
    : QObject(window), m_window(window), m_canvas(canvas) {
    qApp->installEventFilter(this);
}

EnterToCanvas::~EnterToCanvas() {
    qApp->removeEventFilter(this);
}

bool EnterToCanvas::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() != QEvent::KeyPress)
        return false;
    auto* key = static_cast<QKeyEvent*>(event);
    if (key->key() != Qt::Key_Return && key->key() != Qt::Key_Enter)
        return false;
    auto* widget = qobject_cast<QWidget*>(watched);
    // the focus widget only: a spin box passes the key on to its own line edit
    if (!widget || widget != QApplication::focusWidget() || widget->window() != m_window ||
        widget == m_canvas)
        return false;
    if (!qobject_cast<QLineEdit*>(widget) && !qobject_cast<QAbstractSpinBox*>(widget))
        return false;
    // after the field has read its text: a refused value marks the field invalid
    QTimer::singleShot(0, this, [this, field = QPointer<QWidget>(widget)] {
        if (field && QApplication::focusWidget() == field && !field->property("invalid").toBool())
            m_canvas->setFocus(Qt::OtherFocusReason);
    });
    return false;
}

} // namespace chaplygin::ui
