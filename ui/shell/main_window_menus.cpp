// The main window's menus and their actions (File, Edit, View, Animation, Methods, Gallery,
// Lecture, Compare, Help), kept apart from main_window.cpp, which builds and wires the docks.
#include "shell/main_window.h"

#include "canvas/plan_tool.h"
#include "canvas/scene_canvas.h"
#include "common/atomic_file.h"
#include "common/input_error.h"
#include "document/file_dialogs.h"
#include "document/method_names.h"
#include "document/pin_set.h"
#include "document/scene_command.h"
#include "document/scene_document.h"
#include "document/scene_files.h"
#include "document/scene_texts.h"
#include "lab/gallery.h"
#include "panels/accuracy_readout.h"
#include "panels/methods_panel.h"
#include "panels/parameters_panel.h"
#include "panels/path_panel.h"
#include "panels/sweep_panel.h"
#include "plots/plot_export.h"
#include "plots/plots_panel.h"
#include "scene/presets.h"
#include "scene/scene_json.h"
#include "shell/animation_dialog.h"
#include "shell/body_display_menu.h"
#include "shell/dock_layout.h"
#include "shell/elided_label.h"
#include "shell/export_report.h"
#include "shell/gallery_menu.h"
#include "shell/instruments.h"
#include "shell/introduction_window.h"
#include "shell/language_menu.h"
#include "shell/measuring.h"
#include "shell/pen_actions.h"
#include "shell/perturbation_controls.h"
#include "shell/playback.h"
#include "shell/presentation_mode.h"
#include "shell/space_to_play.h"
#include "shell/timeline_bar.h"
#include "shell/window_layout.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QLocale>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>
#include <QUndoStack>
#include <QVBoxLayout>

#include <algorithm>
#include <exception>

namespace chaplygin::ui {

void MainWindow::buildMenus() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(tr("&New"), QKeySequence::New, this, &MainWindow::newScene);
    file->addAction(tr("&Open\u2026"), QKeySequence::Open, this, &MainWindow::openDialog);
    m_recentMenu = file->addMenu(tr("Open &Recent"));
    rebuildRecentMenu();
    file->addAction(tr("&Save"), QKeySequence::Save, this, [this] { saveDialog(false); });
    file->addAction(tr("Save &As\u2026"), QKeySequence::SaveAs, this, [this] { saveDialog(true); });
    installSaveAnnotationsAction(this, *file);
    file->addSeparator();
    QAction* copyLinkAction = file->addAction(tr("Copy &link"), QKeySequence(tr("Ctrl+Shift+C")),
                                              this, [this] { copyLink(); });
    copyLinkAction->setObjectName(QStringLiteral("copyLinkAction"));
    copyLinkAction->setStatusTip(tr("Put a chaplygin-lab: link that holds this scene on the "
                                    "clipboard, to paste into a chat, a course page or an e-mail"));
    QAction* openLinkAction =
        file->addAction(tr("Open lin&k\u2026"), this, &MainWindow::openLinkDialog);
    openLinkAction->setObjectName(QStringLiteral("openLinkAction"));
    file->addSeparator();
    file->addAction(tr("Export &plots\u2026"), QKeySequence(tr("Ctrl+E")), this,
                    &MainWindow::exportPlotsDialog);
    file->addAction(tr("Export &CSV\u2026"), QKeySequence(tr("Ctrl+Shift+E")), this,
                    &MainWindow::exportCsvDialog);
    file->addAction(tr("Export &animation\u2026"), this, &MainWindow::exportAnimationDialog);
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    QAction* undo = m_document->undoStack()->createUndoAction(this, tr("&Undo"));
    undo->setObjectName(QStringLiteral("undoAction"));
    undo->setShortcut(QKeySequence::Undo);
    QAction* redo = m_document->undoStack()->createRedoAction(this, tr("&Redo"));
    redo->setObjectName(QStringLiteral("redoAction"));
    // Ctrl+Y and Ctrl+Shift+Z on every platform
    QList<QKeySequence> redoKeys = QKeySequence::keyBindings(QKeySequence::Redo);
    for (const QKeySequence& k : {QKeySequence(tr("Ctrl+Y")), QKeySequence(tr("Ctrl+Shift+Z"))})
        if (!redoKeys.contains(k))
            redoKeys << k;
    redo->setShortcuts(redoKeys);
    m_redoAction = redo;
    edit->addAction(undo);
    edit->addAction(redo);
    edit->addSeparator();
    // pose to pose (docs/physics.md §10): the Plan tool, in the menu, on the toolbar and a key
    m_planAction = edit->addAction(tr("P&lan a motion (pose to pose)"));
    m_planAction->setObjectName(QStringLiteral("planAction"));
    m_planAction->setCheckable(true);
    m_planAction->setShortcut(QKeySequence(tr("Ctrl+Shift+T")));
    m_planAction->setIconText(tr("Plan"));
    m_planAction->setToolTip(tr("Plan: drag the target pose (its dot and its heading's handle; "
                                "Shift snaps) and see every genuine vakonomic motion that "
                                "reaches it, the fastest in full; click one to choose it"));
    connect(m_planAction, &QAction::toggled, m_canvas, &SceneCanvas::setPlanMode);
    connect(m_canvas, &SceneCanvas::planModeChanged, m_planAction, &QAction::setChecked);
    QAction* playPlan = edit->addAction(tr("Play the planned motion"));
    playPlan->setObjectName(QStringLiteral("playPlanAction"));
    playPlan->setIconText(tr("Play plan"));
    playPlan->setShortcut(QKeySequence(tr("Ctrl+Shift+Space")));
    playPlan->setToolTip(tr("The genuine vakonomic body along the chosen motion, with the free "
                            "ghost from the same start"));
    playPlan->setEnabled(false);
    connect(playPlan, &QAction::triggered, m_canvas->planTool(), &PlanTool::play);
    connect(m_canvas, &SceneCanvas::planModeChanged, playPlan, &QAction::setEnabled);
    QAction* trackPlan = edit->addAction(tr("&Track this plan"));
    trackPlan->setObjectName(QStringLiteral("trackPlanAction"));
    trackPlan->setIconText(tr("Track plan"));
    trackPlan->setToolTip(tr("Make the chosen motion's knife track the path: the controlled body "
                             "and the genuine vakonomic body then coincide"));
    trackPlan->setEnabled(false);
    connect(trackPlan, &QAction::triggered, m_canvas->planTool(), &PlanTool::trackPlan);
    connect(m_canvas, &SceneCanvas::planModeChanged, trackPlan, &QAction::setEnabled);
    m_timeline->addSeparator();
    m_timeline->addAction(m_planAction);
    m_timeline->addAction(playPlan);
    m_timeline->addAction(trackPlan);
    installMeasureAction(this, *edit);
    installPenActions(this, *edit, *undo);

    QMenu* view = m_viewMenu = menuBar()->addMenu(tr("&View"));
    view->setObjectName(QStringLiteral("viewMenu"));
    view->addAction(m_docks.path->toggleViewAction());
    view->addAction(m_docks.parameters->toggleViewAction());
    view->addAction(m_docks.plots->toggleViewAction());
    view->addAction(m_docks.methods->toggleViewAction());
    view->addAction(m_docks.accuracy->toggleViewAction());
    view->addAction(m_docks.sweep->toggleViewAction());
    view->addAction(m_timeline->toggleViewAction());
    view->addSeparator();
    view->addAction(tr("&Fit the path"), QKeySequence(tr("Ctrl+0")), m_canvas,
                    &SceneCanvas::fitScene)
        ->setStatusTip(tr("Frame the path and the controlled body (F on the canvas)"));
    view->addAction(tr("Fit &everything that moves"), QKeySequence(tr("Shift+F")), m_canvas,
                    &SceneCanvas::fitEverything)
        ->setObjectName(QStringLiteral("fitEverythingAction"));
    m_followAction = view->addAction(tr("F&ollow body"));
    m_followAction->setCheckable(true);
    m_followAction->setShortcut(QKeySequence(tr("Ctrl+B")));
    connect(m_followAction, &QAction::toggled, m_canvas, &SceneCanvas::setFollowing);
    connect(m_canvas, &SceneCanvas::followBodyChanged, m_followAction, &QAction::setChecked);
    QAction* vakonomic = m_vakonomicAction = view->addAction(tr("Genuine &vakonomic body"));
    vakonomic->setObjectName(QStringLiteral("showVakonomicAction"));
    vakonomic->setCheckable(true);
    vakonomic->setChecked(m_canvas->showsVakonomic());
    vakonomic->setToolTip(tr("Draw a third body whose multiplier obeys its own equation (21): it "
                             "cannot follow the path"));
    connect(vakonomic, &QAction::toggled, m_canvas, &SceneCanvas::setShowVakonomic);
    view->addAction(tr("Zoom &in"), QKeySequence::ZoomIn, this, [this] { m_canvas->zoomBy(1.25); });
    view->addAction(tr("Zoom &out"), QKeySequence::ZoomOut, this,
                    [this] { m_canvas->zoomBy(0.8); });
    // the time plots' time axis: follow the cursor, the whole run, zoom about the cursor
    QMenu* plotTime = view->addMenu(tr("Plots' &time"));
    plotTime->setObjectName(QStringLiteral("plotTimeMenu"));
    plotTime->addAction(m_plots->followCursorAction());
    plotTime->addAction(m_plots->wholeRunAction());
    plotTime->addAction(m_plots->zoomInTimeAction());
    plotTime->addAction(m_plots->zoomOutTimeAction());
    view->addSeparator();
    m_bodyMenu = new BodyDisplayMenu(this);
    view->addMenu(m_bodyMenu);
    connect(m_bodyMenu, &BodyDisplayMenu::styleChosen, this, &MainWindow::setUserStyle);
    view->addAction(m_presentation->toggleAction());
    view->addMenu(m_presentation->makeScaleMenu(view));
    view->addMenu(new LanguageMenu(view));

    QMenu* play = menuBar()->addMenu(tr("&Animation"));
    play->addAction(m_timeline->playAction());
    play->addAction(m_timeline->stepBackAction());
    play->addAction(m_timeline->stepForwardAction());
    play->addAction(m_timeline->loopAction());
    play->addAction(m_timeline->startAction());
    play->addAction(m_timeline->endAction());
    play->addAction(m_timeline->secondBackAction());
    play->addAction(m_timeline->secondForwardAction());
    play->addMenu(m_timeline->makeSpeedMenu(play));
    m_playNewScenes = play->addAction(tr("Play &new scenes at once"));
    m_playNewScenes->setCheckable(true);
    if (m_useSettings)
        m_playNewScenes->setChecked(
            QSettings().value(QStringLiteral("animation/playNewScenes"), false).toBool());
    connect(m_playNewScenes, &QAction::toggled, this, [this](bool on) {
        if (m_useSettings)
            QSettings().setValue(QStringLiteral("animation/playNewScenes"), on);
    });
    play->addSeparator();
    // keyboard control of a demo: the paper's presets on 1 ... 4 (Page Up/Down: the Lecture menu)
    const std::vector<std::string> presets = presetNames();
    for (int i = 0; i < int(presets.size()) && i < 9; ++i)
        play->addAction(tr("Preset %1: %2").arg(i + 1).arg(sceneText(presets[i])),
                        QKeySequence(Qt::Key_1 + i), this, [this, i] { choosePresetNumber(i); });

    QMenu* methods = menuBar()->addMenu(tr("&Methods"));
    methods->addAction(tr("Compute &work-precision"), QKeySequence(tr("Ctrl+Shift+W")), this,
                       [this] {
                           showMethodsDock();
                           m_methods->start();
                       });
    methods->addAction(tr("&Cancel work-precision"), m_methods, &MethodsPanel::cancel);
    auto* gallery = new GalleryMenu(this);
    menuBar()->addMenu(gallery);
    connect(gallery, &GalleryMenu::entryChosen, this, &MainWindow::loadGalleryEntry);
    buildLectureMenu();

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&Help for this part of the window"), QKeySequence::HelpContents, this,
                    &MainWindow::showContextHelp);
    help->addAction(tr("&What am I looking at?"), this, &MainWindow::showIntroduction);
    help->addAction(tr("&User guide"), this, [this] { showHelp(QStringLiteral("user-guide.md")); });
    help->addAction(tr("&Physics notes"), this, [this] { showHelp(QStringLiteral("physics.md")); });
    help->addAction(tr("&Numerical methods"), this,
                    [this] { showHelp(QStringLiteral("numerics.md")); });
    help->addAction(tr("&About Chaplygin Lab"), this,
                    [this] { QMessageBox::about(this, tr("About Chaplygin Lab"), aboutText()); });
}

} // namespace chaplygin::ui
