#pragma once
#include <QWidget>

class QPushButton;
class QTableWidget;

namespace chaplygin::ui {

class SceneDocument;

/// The Values dock: every column of the CSV (File > Export CSV) with its unit at the time shown,
/// read from the document's Solution, and a Copy button that puts them on the clipboard as
/// tab-separated lines (name, value, unit) for a spreadsheet.
class ValuesPanel : public QWidget {
    Q_OBJECT
  public:
    explicit ValuesPanel(SceneDocument* document, QWidget* parent = nullptr);

    /// Shows the values at time t [s] (clamped to the horizon).
    void setTime(double t);
    double time() const { return m_time; }
    /// What Copy puts on the clipboard: a header line, then one line per column, full precision.
    QString tabSeparated() const;
    QTableWidget* table() const { return m_table; }
    QPushButton* copyButton() const { return m_copy; }

  public slots:
    void copy();

  private:
    void refresh();

    SceneDocument* m_document;
    QTableWidget* m_table;
    QPushButton* m_copy;
    double m_time = 0;
};

} // namespace chaplygin::ui
