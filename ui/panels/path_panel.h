#pragma once
#include "scene/scene.h"

#include <QWidget>

#include <utility>

class QComboBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QPushButton;
class QRadioButton;

namespace chaplygin::ui {

class NumberField;

/// The path editor: the paper's presets, a typed graph y(x) or parametric x(u), y(u) with its
/// range (errors inline; the last valid path stays), and freehand drawing on the canvas with
/// pivot or smooth corners. The graph and the parametric path keep a range each. The corner
/// settings belong to the drawn path they show: a loaded scene's drawn path shows its own, and a
/// new drawing starts with the user's own choice (smooth, 3 spacings until one is made).
class PathPanel : public QWidget {
    Q_OBJECT
  public:
    explicit PathPanel(QWidget* parent = nullptr);

    /// Shows the scene's path without emitting anything.
    void setScene(const Scene& scene);
    /// Shows an error under the expressions (empty clears it).
    void showError(const QString& message);
    QString errorText() const;
    /// The corners a new drawing gets.
    CornerMode drawCorners() const { return m_newCorners; }
    /// Spline bandwidth for a new smooth drawing, in point spacings (0 interpolates).
    double drawSmoothing() const { return m_newSmoothing; }
    /// The least turn [degrees] that is a pivot corner in a new drawing.
    double drawCornerAngle() const { return m_newCornerAngle; }
    NumberField* smoothingSpin() const { return m_smoothing; }
    NumberField* cornerAngleField() const { return m_cornerAngle; }

    QLineEdit* graphEdit() const { return m_y; }
    QLineEdit* xOfUEdit() const { return m_xu; }
    QLineEdit* yOfUEdit() const { return m_yu; }
    NumberField* fromSpin() const { return m_from; }
    NumberField* toSpin() const { return m_to; }
    QRadioButton* parametricButton() const { return m_parametric; }
    QRadioButton* graphButton() const { return m_graph; }
    QPushButton* applyButton() const { return m_apply; }
    QPushButton* drawButton() const { return m_draw; }
    QComboBox* presetBox() const { return m_preset; }
    QComboBox* cornersBox() const { return m_corners; }

  signals:
    void presetChosen(const QString& name);
    /// The user applied a typed path (Enter or Apply).
    void pathTyped(const PathSource& source);
    void drawModeToggled(bool on);
    /// The corner mode, the smoothing or the corner angle changed while the current path is a
    /// polyline.
    void drawOptionsChanged(CornerMode mode, double smoothing, double cornerAngle);

  protected:
    void keyPressEvent(QKeyEvent* e) override;

  private:
    void applyTyped();
    void updateKind();
    /// The corner widgets show the current drawn path's settings, or in draw mode (and for a
    /// path that is not drawn) those of the next drawing.
    void showDrawSettings();
    std::pair<double, double>& rangeOf(bool graph) { return graph ? m_graphRange : m_uRange; }

    Scene m_scene;
    QComboBox* m_preset;
    QLabel* m_presetInfo;
    QRadioButton* m_graph;
    QRadioButton* m_parametric;
    QLineEdit* m_y;
    QLineEdit* m_xu;
    QLineEdit* m_yu;
    NumberField* m_from;
    NumberField* m_to;
    QLabel* m_rangeLabel;
    QPushButton* m_apply;
    QLabel* m_error;
    QPushButton* m_draw;
    QComboBox* m_corners;
    NumberField* m_smoothing;
    NumberField* m_cornerAngle;
    QLabel* m_polylineInfo;
    QFormLayout* m_drawnForm;
    bool m_drawing = false;
    // a stroke was drawn since draw mode began: the corners and smoothing shown are its own
    bool m_strokeDrawn = false;
    bool m_showing = false; // the widgets are being set to show settings, not changed by the user
    CornerMode m_newCorners;
    double m_newSmoothing;
    double m_newCornerAngle;
    bool m_rangeIsGraph = true; // which kind's range the spin boxes show
    std::pair<double, double> m_graphRange, m_uRange;
};

} // namespace chaplygin::ui
