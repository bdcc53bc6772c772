#include "shell/perturbation_controls.h"

#include "canvas/scene_canvas.h"
#include "document/scene_document.h"
#include "panels/perturbation_panel.h"
#include "shell/main_window.h"
#include "shell/presentation_mode.h"

#include <QAction>
#include <QDockWidget>
#include <QMenu>
#include <QMenuBar>
#include <QScrollArea>

namespace chaplygin::ui {

void installPerturbationControls(MainWindow* window, QMenu& viewMenu, QAction& showVakonomic,
                                 QDockWidget& parametersDock) {
    SceneDocument* doc = window->document();
    SceneCanvas* canvas = window->canvas();
    auto* panel = new PerturbationPanel;
    auto* dock = new QDockWidget(MainWindow::tr("Perturbation"), window);
    dock->setObjectName(QStringLiteral("perturbationDock"));
    // taller than a low window: it scrolls, as the parameters dock does
    auto* scroll = new QScrollArea;
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setWidget(panel);
    dock->setWidget(scroll);
    window->addDockWidget(Qt::LeftDockWidgetArea, dock);
    window->tabifyDockWidget(&parametersDock, dock);
    parametersDock.raise();
    window->presentation()->addHiddenDock(dock);
    // the panel shows the document's scene after every recompute, an undo among them
    QObject::connect(doc, &SceneDocument::solutionChanged, panel, [doc, panel] {
        panel->setScene(doc->scene());
        panel->showError({});
    });
    QObject::connect(doc, &SceneDocument::errorChanged, panel, [doc, panel](const SceneError& e) {
        panel->setScene(doc->scene());
        panel->showError(e.part == SceneError::Part::Perturbation ? e.message : QString());
    });
    QObject::connect(panel, &PerturbationPanel::sceneEdited, window,
                     [window](const Scene& scene, const QString& text, const QString& key) {
                         window->editScene(scene, text, key);
                     });
    // grab and push: the push at the drag's time, its sideways distance as push_dy
    QObject::connect(canvas, &SceneCanvas::pushDragged, window,
                     [window, doc](double t, double pushDy) {
                         Scene next = doc->scene();
                         Perturbation p = next.perturbation.value_or(Perturbation());
                         p.tPush = t;
                         p.pushDy = pushDy;
                         next.perturbation = p;
                         window->editScene(next, MainWindow::tr("Push the body"));
                     });

    QMenu* view = &viewMenu;
    const QList<QAction*> actions = view->actions();
    const qsizetype at = actions.indexOf(&showVakonomic);
    QAction* before = at >= 0 ? actions.value(at + 1) : nullptr;
    QAction* open = new QAction(MainWindow::tr("Pushed body, &open loop"), view);
    open->setObjectName(QStringLiteral("showOpenLoopAction"));
    open->setCheckable(true);
    open->setChecked(canvas->showsOpenLoop());
    open->setToolTip(MainWindow::tr("With a perturbation: the body that keeps the nominal "
                                    "\u03bb(t) after the push"));
    QObject::connect(open, &QAction::toggled, canvas, &SceneCanvas::setShowOpenLoop);
    QAction* closed = new QAction(MainWindow::tr("Pushed body, &closed loop"), view);
    closed->setObjectName(QStringLiteral("showClosedLoopAction"));
    closed->setCheckable(true);
    closed->setChecked(canvas->showsClosedLoop());
    closed->setToolTip(
        MainWindow::tr("With a perturbation: the body the feedback steers back to the path"));
    QObject::connect(closed, &QAction::toggled, canvas, &SceneCanvas::setShowClosedLoop);
    view->insertAction(before, open);
    view->insertAction(before, closed);
    QAction* first = view->actions().value(0);
    view->insertAction(first, dock->toggleViewAction());
}

} // namespace chaplygin::ui
