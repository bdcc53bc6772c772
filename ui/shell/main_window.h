#pragma once
#include "document/autosave.h"
#include "scene/scene.h"
#include "shell/dock_layout.h"

#include <QMainWindow>
#include <QPointer>

#include <functional>
#include <optional>

class QAction;
class QDockWidget;
class QLabel;
class QMenu;
class QUndoStack;

namespace chaplygin::ui {

class AccuracyReadout;
class BodyDisplayMenu;
struct CanvasStyle;
struct SceneError;
class ElidedLabel;
class ExportReport;
class HelpWindow;
class IntroductionWindow;
class LecturePanel;
class PresentationMode;
class MethodsPanel;
class ParametersPanel;
class PathPanel;
class Playback;
class PlotsPanel;
class SceneCanvas;
class SceneDocument;
class SweepPanel;
class TimelineBar;
class PlanTimeline;
struct AnimationSettings;

/// The Chaplygin Lab window: the scene canvas in the centre, path, parameters and plots docks,
/// the timeline toolbar, and the File, Edit, View and Help menus. It builds the widgets and wires
/// them to the SceneDocument, which holds the scene, its undo stack and its files.
class MainWindow : public QMainWindow {
    Q_OBJECT
  public:
    /// useSettings: restore and save geometry, dock layout and recent files (off for tests and
    /// screenshots).
    explicit MainWindow(bool useSettings = true, QWidget* parent = nullptr);
    ~MainWindow() override;

    /// SceneDocument::load, then the view from t = 0 with the scene fitted. Throws InputError
    /// when the scene does not solve.
    void loadScene(const Scene& scene);
    /// SceneDocument::edit (one undo step).
    void editScene(const Scene& scene, const QString& description, const QString& mergeKey = {});

    /// File operations without dialogs; each returns false and shows why on failure.
    bool openFile(const QString& path);
    /// Opens a scene link (chaplygin-lab:..., File > Copy link) as a new untitled scene; a damaged
    /// link, or one whose scene does not solve, keeps the current scene and shows why.
    bool openLink(const QString& link);
    /// File > Copy link: the scene's link on the clipboard; false, showing why, when the scene
    /// does not solve or is too large for a link.
    bool copyLink();
    bool saveFile(const QString& path);
    /// Whether File > Save would change the scene's file: the scene was edited since it was
    /// opened or saved, or the pen's marks, when they are saved with it, changed.
    bool hasUnsavedChanges() const;
    bool exportPlotsTo(const QString& dir, const QStringList& formats);
    bool exportCsvTo(const QString& path);
    /// Writes the animation with a progress dialog; false when cancelled or failed (the
    /// reason in lastFileError(), empty when cancelled).
    bool exportAnimationTo(const AnimationSettings& settings);
    /// File > Export animation: the settings dialog, then exportAnimationTo.
    void exportAnimationDialog();
    SweepPanel* sweepPanel() const { return m_sweep; }
    /// Shows and raises the Sweep dock.
    void showSweepDock();

    /// Gives the canvas most of the window (balanceDocks in shell/dock_layout.h).
    void balanceDocks();
    /// Shows and raises the parameters dock (over the path dock when they share tabs).
    void showParametersDock();

    /// Loads a gallery scene as one undo step and shows its explanation beside the
    /// animation; a scene the core refuses keeps the current one and shows the refusal.
    /// Returns whether the scene was loaded. Throws InputError for unknown names.
    bool loadGalleryEntry(const QString& name);

    /// The last message shown for a failed file operation.
    const QString& lastFileError() const { return m_lastFileError; }

    SceneDocument* document() const { return m_document; }
    Playback* playback() const { return m_playback; }
    SceneCanvas* canvas() const { return m_canvas; }
    ParametersPanel* parametersPanel() const { return m_parameters; }
    PathPanel* pathPanel() const { return m_path; }
    PlotsPanel* plotsPanel() const { return m_plots; }
    MethodsPanel* methodsPanel() const { return m_methods; }
    AccuracyReadout* accuracyReadout() const { return m_accuracy; }
    /// Shows and raises the Methods dock.
    void showMethodsDock();
    TimelineBar* timeline() const { return m_timeline; }
    /// The planned motion's clock, which the timeline shows while a motion is chosen in plan mode.
    PlanTimeline* planTimeline() const { return m_planTimeline; }
    QUndoStack* undoStack() const;
    QAction* followAction() const { return m_followAction; }
    /// Edit > Plan a motion: the canvas's Plan tool (docs/physics.md §10).
    QAction* planAction() const { return m_planAction; }
    QMenu* recentMenu() const { return m_recentMenu; }
    PresentationMode* presentation() const { return m_presentation; }
    BodyDisplayMenu* bodyDisplayMenu() const { return m_bodyMenu; }
    ElidedLabel* statusLabel() const { return m_status; }
    /// What the last export wrote, and where (the status bar's "Open folder").
    ExportReport* exportReport() const { return m_exportReport; }
    QAction* redoAction() const { return m_redoAction; }
    /// Whether a new scene (preset, gallery, typed or drawn path) starts playing at t = 0
    /// (QSettings "animation/playNewScenes"); otherwise it waits, paused, at t = 0.
    QAction* playNewScenesAction() const { return m_playNewScenes; }
    /// The help window (created on first use), showing document at section.
    HelpWindow* showHelp(const QString& document = {}, const QString& section = {});
    /// Help > What am I looking at?: the explanation window (created on first use).
    IntroductionWindow* showIntroduction();
    /// At start: the explanation, unless dismissed ("Don't show this at start"); never for a
    /// window without user settings (tests, screenshots). Returns whether it was shown.
    bool offerIntroduction();
    IntroductionWindow* introduction() const;
    /// F1: the help section about the widget that has the focus.
    void showContextHelp();
    /// Loads the paper's preset number index (0 ... 3; keys 1 ... 4).
    void choosePresetNumber(int index);
    /// Loads the next (+1) or previous (-1) gallery scene (Page Down / Page Up).
    void stepGallery(int direction);

    // The lecture (main_window_lecture.cpp): scenes in an order of one's own

    /// The Lecture dock's list and the open lecture.
    LecturePanel* lecturePanel() const { return m_lecture; }
    /// Page Down (+1) and Page Up (-1): the open lecture's next or previous scene, else the
    /// gallery's.
    void stepScene(int direction);
    /// Shows the lecture's entry index as one undo step (as a gallery scene); a scene that does
    /// not solve keeps the current one, says why and returns false.
    bool showLectureEntry(int index);
    /// Lecture > Add the current scene: after the current entry (a new lecture when none is open).
    void addSceneToLecture();
    /// Opens a lecture file and shows its first scene; false, showing why, when it cannot be read.
    bool openLecture(const QString& path);
    /// Writes the lecture atomically; false, showing why, on failure.
    bool saveLecture(const QString& path);
    /// The About text (version from the build, licence, credits, the paper).
    static QString aboutText();

    /// After an abnormal end of an earlier run: offers the newest unsaved scene it left
    /// (Autosave), asking `restore` (by default a dialog saying from when). A restored scene
    /// is the document, modified, with its own file name; either way the copy is removed.
    /// Returns whether a scene was restored.
    using RestoreQuestion = std::function<bool(const Autosave::Orphan&)>;
    bool offerRestore(const RestoreQuestion& restore = {});
    /// The copy of the unsaved scene (null for tests and screenshots).
    Autosave* autosave() const;

  protected:
    void closeEvent(QCloseEvent* e) override;

  private:
    void buildMenus();
    /// The Lecture menu and dock.
    void buildLectureMenu();
    void newLecture();
    void openLectureDialog();
    bool saveLectureDialog(bool askName);
    /// Asks to save the lecture's unsaved changes; false when the user cancels.
    bool maybeSaveLecture();
    /// "Scene i of n" in the status bar, the window title and the Notes dock's title.
    void showLecturePosition();
    /// The words "scene i of n", empty when no lecture entry is shown.
    QString lecturePosition() const;
    void rebuildRecentMenu();
    /// The panels show a scene the document has applied.
    void showScene(const Scene& scene, bool pathChanged);
    void onSolutionChanged();
    void onDocumentError(const SceneError& error);
    void onTime(double t);
    void choosePreset(const QString& name);
    /// A typed path is a new scene fitted to the view; a drawn one a new scene in the view it
    /// was drawn in; an edit of the drawn one (a point, the corners) keeps time and view (the
    /// view moves only when the path leaves it).
    enum class PathChange { Typed, Drawn, Edited };
    void setPath(const PathSource& source, const QString& description, PathChange change);
    /// Asks to save unsaved changes; false when the user cancels.
    bool maybeSave();
    void newScene();
    void openDialog();
    void openLinkDialog();
    bool saveDialog(bool askName);
    void exportPlotsDialog();
    void exportCsvDialog();
    /// The Plots dock in front of its tabs, when it is open.
    void showPlotsInFront();
    void showFileError(const QString& message);
    void updateTitle();
    /// A new scene starts at t = 0, paused or playing (playNewScenesAction).
    void startNewScene();
    void setUserStyle(const CanvasStyle& style);

    bool m_useSettings;
    SceneDocument* m_document;
    Playback* m_playback;
    SceneCanvas* m_canvas;
    PathPanel* m_path;
    ParametersPanel* m_parameters;
    PlotsPanel* m_plots;
    MethodsPanel* m_methods;
    AccuracyReadout* m_accuracy;
    TimelineBar* m_timeline;
    PlanTimeline* m_planTimeline = nullptr;
    SweepPanel* m_sweep;
    Docks m_docks;
    std::optional<Scene> m_noteScene; // the scene the accuracy dock's note is about
    QMenu* m_recentMenu = nullptr;
    QMenu* m_viewMenu = nullptr;
    QAction* m_vakonomicAction = nullptr; // View > Genuine vakonomic body
    QAction* m_followAction = nullptr;
    QAction* m_planAction = nullptr;
    ElidedLabel* m_status;
    ExportReport* m_exportReport;
    PresentationMode* m_presentation = nullptr;
    BodyDisplayMenu* m_bodyMenu = nullptr;
    HelpWindow* m_help = nullptr;
    QPointer<IntroductionWindow> m_intro;
    QAction* m_redoAction = nullptr;
    QAction* m_playNewScenes = nullptr;
    int m_galleryIndex = -1;
    LecturePanel* m_lecture = nullptr;
    QDockWidget* m_lectureDock = nullptr;
    QLabel* m_lecturePosition = nullptr;
    QString m_lastFileError;
};

} // namespace chaplygin::ui
