#include "shell/main_window.h"

#include "canvas/pen_tool.h"
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
#include "plots/plots_panel.h"
#include "scene/lecture.h"
#include "scene/presets.h"
#include "scene/scene_json.h"
#include "shell/body_display_menu.h"
#include "shell/dock_layout.h"
#include "shell/elided_label.h"
#include "shell/enter_to_canvas.h"
#include "shell/export_report.h"
#include "shell/gallery_menu.h"
#include "shell/instruments.h"
#include "shell/introduction_window.h"
#include "shell/language_menu.h"
#include "shell/measuring.h"
#include "shell/perturbation_controls.h"
#include "shell/plan_readouts.h"
#include "shell/plan_timeline.h"
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

MainWindow::MainWindow(bool useSettings, QWidget* parent)
    : QMainWindow(parent), m_useSettings(useSettings),
      m_document(new SceneDocument(this, useSettings)), m_playback(new Playback(this)) {
    m_canvas = new SceneCanvas(m_document);
    setCentralWidget(m_canvas);

    m_path = new PathPanel;
    m_parameters = new ParametersPanel;
    m_plots = new PlotsPanel(m_document);
    m_methods = new MethodsPanel(m_document);
    m_sweep = new SweepPanel(m_document);
    m_accuracy = new AccuracyReadout(m_document);
    m_docks = placeDocks(this, {m_path, m_parameters, m_plots, m_methods, m_sweep, m_accuracy});

    m_timeline = new TimelineBar(m_playback, this);
    addToolBar(Qt::BottomToolBarArea, m_timeline);
    m_status = new ElidedLabel;
    statusBar()->addWidget(m_status, 1);
    m_exportReport = new ExportReport(statusBar());
    m_presentation = new PresentationMode(
        this, m_canvas, m_plots,
        {m_docks.path, m_docks.parameters, m_docks.methods, m_docks.sweep, m_docks.accuracy},
        {m_timeline});
    m_timeline->addAction(m_presentation->toggleAction());
    new SpaceToPlay(this, m_timeline->playAction());
    new EnterToCanvas(this, m_canvas);

    buildMenus();
    setUserStyle(m_useSettings ? CanvasStyle::load(QSettings()) : CanvasStyle());
    connect(m_plots, &PlotsPanel::exportFailed, this, &MainWindow::showFileError);

    connect(m_document, &SceneDocument::solutionChanged, this, &MainWindow::onSolutionChanged);
    connect(m_document, &SceneDocument::errorChanged, this, &MainWindow::onDocumentError);
    connect(m_document, &SceneDocument::fileNameChanged, this, &MainWindow::updateTitle);
    connect(m_document, &SceneDocument::modifiedChanged, this, &MainWindow::updateTitle);
    // the pen's marks, when they are saved with the scene, are part of what is unsaved
    connect(m_canvas->penTool(), &PenTool::marksChanged, this, &MainWindow::updateTitle);
    connect(m_canvas->penTool(), &PenTool::savesWithSceneChanged, this, &MainWindow::updateTitle);
    connect(m_document, &SceneDocument::sceneApplied, this, &MainWindow::showScene);
    // a scene that comes with a plan shows it (docs/physics.md §10)
    connect(m_document, &SceneDocument::sceneApplied, this,
            [this](const Scene& scene, bool pathChanged) {
                if (pathChanged && scene.plan)
                    m_canvas->setPlanMode(true);
            });
    connect(m_document, &SceneDocument::recentFilesChanged, this, &MainWindow::rebuildRecentMenu);
    connect(m_playback, &Playback::timeChanged, this, &MainWindow::onTime);
    connect(m_plots, &PlotsPanel::seekRequested, m_playback, &Playback::seek);
    connect(m_path, &PathPanel::presetChosen, this, &MainWindow::choosePreset);
    connect(m_path, &PathPanel::pathTyped, this,
            [this](const PathSource& s) { setPath(s, tr("Type a path"), PathChange::Typed); });
    connect(m_path, &PathPanel::drawModeToggled, m_canvas, &SceneCanvas::setDrawMode);
    connect(m_path, &PathPanel::drawOptionsChanged, this,
            [this](CornerMode mode, double smoothing, double cornerAngle) {
                PathSource s = m_document->scene().path;
                s.corners = mode;
                s.smoothing = smoothing;
                s.cornerAngle = cornerAngle;
                setPath(s, tr("Change the corners"), PathChange::Edited);
            });
    connect(m_canvas, &SceneCanvas::pathDrawn, this,
            [this](const std::vector<std::pair<double, double>>& points) {
                PathSource s;
                s.kind = PathKind::Polyline;
                s.points = points;
                s.corners = m_path->drawCorners();
                s.smoothing = m_path->drawSmoothing();
                s.cornerAngle = m_path->drawCornerAngle();
                setPath(s, tr("Draw a path"), PathChange::Drawn);
            });
    connect(m_canvas, &SceneCanvas::pointsEdited, this,
            [this](const std::vector<std::pair<double, double>>& points) {
                PathSource s = m_document->scene().path;
                s.points = points;
                setPath(s, tr("Edit the drawn path"), PathChange::Edited);
            });
    // a slider's change: the panel's scene goes straight to the document's undo stack
    auto editParameters = [this](const Scene& scene, const QString& description,
                                 const QString& mergeKey) {
        const QString error = m_document->editParameters(scene, description, mergeKey);
        m_parameters->showError(error);
        if (!error.isEmpty())
            m_parameters->showDerived(nullptr);
    };
    connect(m_parameters, &ParametersPanel::sceneEdited, this, editParameters);
    connect(m_sweep, &SweepPanel::sceneEdited, this, editParameters);
    installInstruments(this, *m_viewMenu, *m_docks.accuracy);
    installValuesDock(this, *m_viewMenu, *m_docks.accuracy);
    installPerturbationControls(this, *m_viewMenu, *m_vakonomicAction, *m_docks.parameters);
    installPlanReadouts(*m_canvas, *m_plots, *m_accuracy);
    m_planTimeline = new PlanTimeline(*m_canvas, *m_timeline, *m_playback, this);

    if (!m_useSettings)
        resize(1280, 800);
    // the path and the plots in front of their tabs (the docks installed since took the front)
    m_docks.path->raise();
    m_docks.plots->raise();
    const QByteArray defaultLayout = saveState();
    const bool firstStart = !m_useSettings || !restoreWindowLayout(this);
    if (firstStart)
        balanceDocks();
    auto* balancer = new DockBalancer(this, m_docks, firstStart, defaultLayout);
    QMenu* view = m_viewMenu;
    // after the docks' toggles
    auto* reset = new QAction(tr("&Reset layout"), view);
    reset->setObjectName(QStringLiteral("resetLayoutAction"));
    connect(reset, &QAction::triggered, balancer, &DockBalancer::resetLayout);
    const QList<QAction*> items = view->actions();
    auto separator =
        std::find_if(items.begin(), items.end(), [](const QAction* a) { return a->isSeparator(); });
    view->insertAction(separator == items.end() ? nullptr : *separator, reset);
    loadScene(presetScene("sinusoid"));
}

MainWindow::~MainWindow() {
    // the document's undo stack signals while it is destroyed, after this window has gone
    m_document->disconnect(this);
}

QUndoStack* MainWindow::undoStack() const {
    return m_document->undoStack();
}

Autosave* MainWindow::autosave() const {
    return m_document->autosave();
}

void MainWindow::balanceDocks() {
    chaplygin::ui::balanceDocks(this, m_docks);
}

void MainWindow::showPlotsInFront() {
    if (m_docks.plots->toggleViewAction()->isChecked())
        m_docks.plots->raise();
}

void MainWindow::showParametersDock() {
    bringDockForward(this, m_docks.parameters);
}

IntroductionWindow* MainWindow::showIntroduction() {
    const bool first = !m_intro;
    if (first)
        m_intro = new IntroductionWindow(m_useSettings, this);
    m_intro->show();
    if (first) // shown, its frame is known
        placeOnScreen(m_intro, m_intro->size(), this);
    m_intro->raise();
    m_intro->activateWindow();
    return m_intro;
}

IntroductionWindow* MainWindow::introduction() const {
    return m_intro;
}

bool MainWindow::offerIntroduction() {
    if (!m_useSettings || !IntroductionWindow::dueAtStart(QSettings()))
        return false;
    showIntroduction();
    return true;
}

void MainWindow::setUserStyle(const CanvasStyle& style) {
    m_presentation->setBaseStyle(style);
    m_bodyMenu->setCanvasStyle(m_presentation->baseStyle());
    if (m_useSettings) {
        QSettings settings;
        m_presentation->baseStyle().save(settings);
    }
}

void MainWindow::startNewScene() {
    m_playback->pause();
    m_playback->seek(0);
    if (m_playNewScenes && m_playNewScenes->isChecked())
        m_playback->play();
}

void MainWindow::rebuildRecentMenu() {
    m_recentMenu->clear();
    const QStringList files = m_document->recentFiles();
    for (const QString& f : files)
        m_recentMenu
            ->addAction(QFileInfo(f).fileName(), this,
                        [this, f] {
                            if (maybeSave())
                                openFile(f);
                        })
            ->setToolTip(f);
    m_recentMenu->setEnabled(!files.isEmpty());
}

void MainWindow::showScene(const Scene& scene, bool pathChanged) {
    if (pathChanged) {
        m_path->setScene(scene);
        m_path->showError({});
        statusBar()->clearMessage(); // messages belong to the scene that produced them
    }
    m_parameters->setScene(scene);
    m_parameters->showError({});
}

void MainWindow::loadScene(const Scene& scene) {
    m_document->loadNow(scene);
    m_playback->seek(0);
    m_canvas->fitScene();
}

void MainWindow::editScene(const Scene& scene, const QString& description,
                           const QString& mergeKey) {
    m_document->edit(scene, description, mergeKey);
}

void MainWindow::choosePreset(const QString& name) {
    // its path on the path worker, as a typed path's
    Scene next;
    try {
        next = presetScene(name.toStdString());
    } catch (const InputError& e) {
        m_path->showError(QString::fromStdString(e.what()));
        return;
    }
    m_document->load(next,
                     {.description = tr("Preset %1").arg(sceneText(name.toStdString())),
                      .loaded =
                          [this, name] {
                              startNewScene();
                              m_canvas->fitScene();
                              // the keys 1 ... 4 replace the scene too: say what came, and how back
                              statusBar()->showMessage(
                                  tr("Preset %1 loaded; Ctrl+Z goes back").arg(name), 8000);
                          },
                      .refused = [this](const SceneError& e) { m_path->showError(e.message); }});
}

void MainWindow::setPath(const PathSource& source, const QString& description, PathChange change) {
    // tabulated on the path worker: errors stay in the panel, the last path stays meanwhile
    const QString tabulating = tr("Tabulating the path\u2026");
    m_document->requestPath(source, [=, this](const QString& error) {
        if (statusBar()->currentMessage() == tabulating)
            statusBar()->clearMessage();
        m_path->showError(error);
        if (!error.isEmpty())
            return;
        Scene next = m_document->scene();
        next.path = source;
        next.preset.clear();
        if (change != PathChange::Typed)
            m_canvas->keepViewForNextPath();
        editScene(next, description);
        m_document->flush();
        if (change != PathChange::Edited) // a new path, not an edit of the drawn one
            startNewScene();
        if (change == PathChange::Typed)
            m_canvas->fitScene();
    });
    if (m_document->pathPending())
        statusBar()->showMessage(tabulating);
}

void MainWindow::onSolutionChanged() {
    const auto& solution = m_document->solution();
    m_playback->setTEnd(solution->tEnd());
    m_timeline->sync();
    m_parameters->showDerived(&solution->system());
    m_status->setFullText(plainModelSummary(*solution)); // the technical words: Accuracy ▸ Details
    if (m_noteScene && m_document->scene() != *m_noteScene) {
        m_noteScene.reset();
        m_accuracy->setNote({}, {});
    }
    updateTitle();
}

void MainWindow::showMethodsDock() {
    // the diagram's legends need about half the height
    bringDockForward(this, m_docks.methods, methodsDockHeight(height()));
}

bool MainWindow::loadGalleryEntry(const QString& name) {
    const GalleryEntry& entry = galleryEntry(name.toStdString());
    // Page Down goes on from here, whether the scene came from the menu or from Page Down
    const auto& entries = galleryEntries();
    for (std::size_t i = 0; i < entries.size(); ++i)
        if (&entries[i] == &entry)
            m_galleryIndex = int(i);
    const QString title = sceneText(entry.title);
    const QString explanation = sceneText(entry.scene.note);
    if (!m_presentation->isActive()) // presenting, the explanation is in the Notes dock
        bringDockForward(this, m_docks.accuracy);
    // vetted before this returns: a refused entry's refusal is its lesson
    try {
        m_document->loadNow(entry.scene, tr("Gallery: %1").arg(title));
    } catch (const InputError& e) {
        const QString refusal = QString::fromStdString(e.what());
        m_noteScene = m_document->scene();
        m_accuracy->setNote(tr("Refused: %1").arg(title),
                            refusal + QStringLiteral("\n\n") + explanation, true);
        statusBar()->showMessage(refusal, 10000);
        if (isVisible() && m_useSettings)
            QMessageBox::warning(this, tr("Gallery: %1").arg(title), refusal);
        return false;
    }
    m_noteScene = entry.scene;
    m_accuracy->setNote(title, explanation);
    statusBar()->clearMessage(); // an earlier refusal no longer applies
    startNewScene();
    m_canvas->fitScene();
    return true;
}

void MainWindow::onDocumentError(const SceneError& error) {
    if (!error.isEmpty()) {
        m_parameters->showError(error.message);
        statusBar()->showMessage(error.message, 8000);
    }
}

void MainWindow::onTime(double t) {
    m_canvas->setTime(t);
    m_plots->setTime(t);
    m_accuracy->setTime(t);
}

bool MainWindow::hasUnsavedChanges() const {
    return m_document->isModified() || m_canvas->penTool()->hasUnsavedMarks();
}

bool MainWindow::maybeSave() {
    if (!m_useSettings || !hasUnsavedChanges())
        return true;
    auto answer = QMessageBox::question(
        this, tr("Chaplygin Lab"), tr("The scene has unsaved changes. Save them?"),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Save)
        return saveDialog(false);
    return answer == QMessageBox::Discard;
}

void MainWindow::newScene() {
    if (!maybeSave())
        return;
    loadScene(presetScene("sinusoid"));
    m_document->setFileName({});
}

bool MainWindow::openFile(const QString& path) {
    // a lecture opens wherever a scene file does (File > Open, the recent files, the command line)
    bool lecture = false;
    try {
        lecture = isLectureText(readLectureOrSceneText(path.toStdString()));
    } catch (const InputError&) {
        // unreadable: the scene reader says why
    }
    if (lecture)
        return openLecture(path);
    try {
        m_document->open(path);
    } catch (const std::exception& e) {
        showFileError(QString::fromStdString(e.what()));
        return false;
    }
    rememberFolder(QStringLiteral("scene"), path); // opened from the recent list or a command line
    showPlotsInFront(); // the Sweep and Methods docks are empty for a scene just opened
    m_playback->seek(0);
    m_canvas->fitScene();
    return true;
}

bool MainWindow::saveFile(const QString& path) {
    const PenTool& pen = *m_canvas->penTool();
    try {
        m_document->save(path, pen.savesWithScene() ? pen.marks() : std::vector<AnnotationMark>{});
    } catch (const std::exception& e) {
        showFileError(QString::fromStdString(e.what()));
        return false;
    }
    m_canvas->penTool()->setMarksSaved();
    updateTitle();
    statusBar()->showMessage(tr("Saved %1").arg(path), 4000);
    return true;
}

void MainWindow::openDialog() {
    if (!maybeSave())
        return;
    QString path = chooseOpenFile(this, tr("Open scene"), QStringLiteral("scene"),
                                  tr("Scenes and lectures (*.json);;All files (*)"));
    if (!path.isEmpty())
        openFile(path);
}

bool MainWindow::saveDialog(bool askName) {
    QString path = m_document->fileName();
    if (askName || path.isEmpty())
        path = chooseSaveFile(this, tr("Save scene"), QStringLiteral("scene"),
                              sceneFileStem(m_document->scene(), m_document->fileName()),
                              tr("Scenes (*.json)"));
    return !path.isEmpty() && saveFile(path);
}

void MainWindow::showSweepDock() {
    bringDockForward(this, m_docks.sweep, sweepDockHeight(height()));
}

void MainWindow::showFileError(const QString& message) {
    m_lastFileError = message;
    statusBar()->showMessage(message, 10000);
    if (isVisible() && !QCoreApplication::closingDown() && m_useSettings)
        QMessageBox::warning(this, tr("Chaplygin Lab"), message);
}

void MainWindow::updateTitle() {
    QString name = m_document->fileName().isEmpty() ? tr("untitled")
                                                    : QFileInfo(m_document->fileName()).fileName();
    QString title = tr("%1%2 \u2014 Chaplygin Lab")
                        .arg(name, hasUnsavedChanges() ? QStringLiteral("*") : QString());
    if (const QString position = lecturePosition(); !position.isEmpty())
        title = tr("Lecture, %1 \u2014 %2").arg(position, title);
    setWindowTitle(title);
}

void MainWindow::closeEvent(QCloseEvent* e) {
    if (!maybeSave() || !maybeSaveLecture()) {
        e->ignore();
        return;
    }
    if (m_useSettings)
        saveWindowLayout(this);
    if (m_document->autosave())
        m_document->autosave()->discard(); // a clean exit leaves nothing to restore
    e->accept();
}

bool MainWindow::offerRestore(const RestoreQuestion& restore) {
    if (!m_document->autosave())
        return false;
    const std::vector<Autosave::Orphan> orphans = m_document->autosave()->orphans();
    if (orphans.empty())
        return false;
    const Autosave::Orphan& newest = orphans.front();
    const bool wanted =
        restore ? restore(newest)
                : QMessageBox::question(
                      this, tr("Restore the unsaved scene?"),
                      tr("Chaplygin Lab ended without saving the scene you were working on. A "
                         "copy was kept at %1. Restore it?")
                          .arg(QLocale().toString(newest.written, QLocale::LongFormat)),
                      QMessageBox::Yes | QMessageBox::No, QMessageBox::Yes) == QMessageBox::Yes;
    bool restored = false;
    if (wanted) {
        try {
            const QString marksRefused = m_document->restore(newest);
            m_playback->seek(0);
            m_canvas->fitScene();
            restored = true;
            if (!marksRefused.isEmpty())
                showFileError(
                    tr("The scene is restored without the pen's marks, which were damaged: %1")
                        .arg(marksRefused));
        } catch (const std::exception& e) {
            showFileError(QString::fromStdString(e.what()));
        }
    }
    Autosave::removeOrphan(newest);
    return restored;
}

} // namespace chaplygin::ui
