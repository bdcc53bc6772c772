#pragma once
#include "shell/animation_export.h"

#include <QDialog>

class QCheckBox;
class QLineEdit;
class QLabel;

namespace chaplygin::ui {

class NumberField;
class SceneDocument;

/// File > Export animation: the output (name.gif, name.mp4 or a folder for PNG frames), frame
/// rate, size, playback speed and whether the plots go beside the canvas.
class AnimationDialog : public QDialog {
    Q_OBJECT
  public:
    explicit AnimationDialog(const AnimationSettings& initial, QWidget* parent = nullptr);
    AnimationSettings settings() const;

    /// defaults with the frame rate, size and "with plots" last exported (QSettings), where
    /// there are such and they are within the dialog's bounds.
    static AnimationSettings remembered(AnimationSettings defaults);
    /// Keeps the frame rate, size and "with plots" of an export for the next dialog.
    static void remember(const AnimationSettings& settings);

    QLineEdit* fileEdit() const { return m_file; }
    NumberField* fpsBox() const { return m_fps; }
    NumberField* widthBox() const { return m_width; }
    NumberField* heightBox() const { return m_height; }
    NumberField* speedBox() const { return m_speed; }
    /// The refusal of a typed value, or empty.
    QString errorText() const;
    QCheckBox* plotsBox() const { return m_plots; }

  private:
    void browse();

    QLineEdit* m_file;
    NumberField* m_fps;
    NumberField* m_width;
    NumberField* m_height;
    NumberField* m_speed;
    QLabel* m_error;
    QCheckBox* m_plots;
};

/// Runs an export with a modal progress dialog (the frames are painted on the UI thread, which
/// owns the widgets; the dialog keeps the window responsive between frames) and a Cancel
/// button. Returns true when the file was written; false when cancelled or failed, with the
/// reason in *error (empty when cancelled). A cancelled or failed export leaves no file.
bool exportAnimationWithProgress(QWidget* parent, SceneDocument* document,
                                 const AnimationSettings& settings, QString* error);

} // namespace chaplygin::ui
