#include "shell/measuring.h"

#include "canvas/scene_canvas.h"
#include "panels/values_panel.h"
#include "shell/main_window.h"
#include "shell/playback.h"
#include "shell/timeline_bar.h"

#include <QAction>
#include <QDockWidget>
#include <QMenu>

namespace chaplygin::ui {

void installMeasureAction(MainWindow* window, QMenu& editMenu) {
    SceneCanvas* canvas = window->canvas();
    QAction* measure = editMenu.addAction(MainWindow::tr("&Measure (ruler, protractor, probe)"));
    measure->setObjectName(QStringLiteral("measureAction"));
    measure->setCheckable(true);
    measure->setShortcut(QKeySequence(MainWindow::tr("Ctrl+Shift+M")));
    measure->setIconText(MainWindow::tr("Measure"));
    measure->setToolTip(MainWindow::tr(
        "Measure (M on the canvas): drag for a ruler, drag again from its end for an angle, "
        "start on a body to measure from its heading; hover the path or a trail for its "
        "values. Esc clears; the scene is not changed"));
    QObject::connect(measure, &QAction::toggled, canvas, &SceneCanvas::setMeasureMode);
    QObject::connect(canvas, &SceneCanvas::measureModeChanged, measure, &QAction::setChecked);
    window->timeline()->addAction(measure);
}

void installValuesDock(MainWindow* window, QMenu& viewMenu, QDockWidget& accuracyDock) {
    auto* values = new ValuesPanel(window->document());
    auto* dock = new QDockWidget(MainWindow::tr("Values"), window);
    dock->setObjectName(QStringLiteral("valuesDock"));
    dock->setWidget(values);
    window->addDockWidget(Qt::RightDockWidgetArea, dock);
    window->tabifyDockWidget(&accuracyDock, dock);
    dock->hide();
    accuracyDock.raise();
    Playback* playback = window->playback();
    QObject::connect(playback, &Playback::timeChanged, values, &ValuesPanel::setTime);
    // shown: the values catch up with the time
    QObject::connect(dock, &QDockWidget::visibilityChanged, values, [values, playback](bool on) {
        if (on)
            values->setTime(playback->time());
    });
    QAction* toggle = dock->toggleViewAction();
    toggle->setShortcut(QKeySequence(MainWindow::tr("Ctrl+Shift+V")));
    viewMenu.insertAction(viewMenu.actions().value(0), toggle);
}

} // namespace chaplygin::ui
