#include "shell/space_to_play.h"

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QKeyEvent>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QTextEdit>
#include <QWidget>

namespace chaplygin::ui {

SpaceToPlay::SpaceToPlay(QWidget* window, QAction* play)
    : QObject(window), m_window(window), m_play(play) {
    qApp->installEventFilter(this);
}

SpaceToPlay::~SpaceToPlay() {
    qApp->removeEventFilter(this);
}

bool SpaceToPlay::isTextField(const QWidget* widget) {
    if (qobject_cast<const QLineEdit*>(widget)) {
        // the line edit inside a spin box holds a number, not text
        const QWidget* parent = widget->parentWidget();
        return !(parent && parent->inherits("QAbstractSpinBox"));
    }
    if (auto* combo = qobject_cast<const QComboBox*>(widget))
        return combo->isEditable();
    if (auto* text = qobject_cast<const QTextEdit*>(widget))
        return !text->isReadOnly();
    if (auto* plain = qobject_cast<const QPlainTextEdit*>(widget))
        return !plain->isReadOnly();
    return false;
}

bool SpaceToPlay::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() != QEvent::ShortcutOverride && event->type() != QEvent::KeyPress)
        return false;
    auto* key = static_cast<QKeyEvent*>(event);
    if (key->key() != Qt::Key_Space || key->modifiers() != Qt::NoModifier || key->isAutoRepeat())
        return false;
    auto* widget = qobject_cast<QWidget*>(watched);
    if (!widget || widget->window() != m_window || isTextField(widget))
        return false;
    if (event->type() == QEvent::ShortcutOverride) {
        // a widget that wants Space for itself (spin box, button, slider, table) must not get it
        event->accept();
        return true;
    }
    if (m_play->isEnabled())
        m_play->trigger();
    return true;
}

} // namespace chaplygin::ui
