#pragma once
// An event filter that counts the events of one type a widget receives (repaints, relayouts).
#include <QEvent>
#include <QObject>

namespace chaplygin::ui::test {

class EventCounter : public QObject {
  public:
    explicit EventCounter(QEvent::Type type) : m_type(type) {}
    int count = 0;
    bool eventFilter(QObject*, QEvent* e) override {
        count += e->type() == m_type ? 1 : 0;
        return false;
    }

  private:
    QEvent::Type m_type;
};

} // namespace chaplygin::ui::test
