#include "panels/values_panel.h"

#include "document/scene_document.h"
#include "scene/csv_columns.h"

#include <QApplication>
#include <QClipboard>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace chaplygin::ui {

ValuesPanel::ValuesPanel(SceneDocument* document, QWidget* parent)
    : QWidget(parent), m_document(document), m_table(new QTableWidget(this)),
      m_copy(new QPushButton(tr("&Copy"), this)) {
    m_table->setColumnCount(3);
    m_table->setHorizontalHeaderLabels({tr("Column"), tr("Value"), tr("Unit")});
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setAccessibleName(tr("Values at the shown time"));
    m_copy->setObjectName(QStringLiteral("copyValuesButton"));
    m_copy->setToolTip(tr("Copy the values as tab-separated lines (column, value, unit)"));
    auto* buttons = new QHBoxLayout;
    buttons->addStretch();
    buttons->addWidget(m_copy);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(m_table);
    layout->addLayout(buttons);
    connect(m_copy, &QPushButton::clicked, this, &ValuesPanel::copy);
    connect(document, &SceneDocument::solutionChanged, this, &ValuesPanel::refresh);
    refresh();
}

void ValuesPanel::setTime(double t) {
    m_time = t;
    if (isVisible())
        refresh();
}

void ValuesPanel::refresh() {
    const auto& solution = m_document->solution();
    if (!solution) {
        m_table->setRowCount(0);
        return;
    }
    const MotionSample m = solution->at(std::clamp(m_time, 0.0, solution->tEnd()));
    const auto columns = csvColumnsWritten(solution->perturbed());
    m_table->setRowCount(int(columns.size()));
    int row = 0;
    for (const CsvColumn& column : columns) {
        auto cell = [&](int col, const QString& text) {
            QTableWidgetItem* item = m_table->item(row, col);
            if (!item) {
                item = new QTableWidgetItem;
                m_table->setItem(row, col, item);
            }
            item->setText(text);
        };
        cell(0, QString::fromUtf8(column.name.data(), qsizetype(column.name.size())));
        cell(1, QString::number(column.value(m), 'g', 6));
        cell(2, QString::fromUtf8(column.unit.data(), qsizetype(column.unit.size())));
        ++row;
    }
}

QString ValuesPanel::tabSeparated() const {
    const auto& solution = m_document->solution();
    if (!solution)
        return {};
    const MotionSample m = solution->at(std::clamp(m_time, 0.0, solution->tEnd()));
    QStringList lines{QStringLiteral("column\tvalue\tunit")};
    for (const CsvColumn& column : csvColumnsWritten(solution->perturbed()))
        lines << QStringLiteral("%1\t%2\t%3")
                     .arg(QString::fromUtf8(column.name.data(), qsizetype(column.name.size())),
                          QString::number(column.value(m), 'g', 17),
                          QString::fromUtf8(column.unit.data(), qsizetype(column.unit.size())));
    return lines.join(QLatin1Char('\n')) + QLatin1Char('\n');
}

void ValuesPanel::copy() {
    QApplication::clipboard()->setText(tabSeparated());
}

} // namespace chaplygin::ui
