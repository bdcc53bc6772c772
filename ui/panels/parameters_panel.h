#pragma once
#include "scene/scene.h"
#include "systems/system_parameters.h"

#include <QString>
#include <QWidget>

#include <map>
#include <string>

class QComboBox;
class QFormLayout;
class QLabel;
class QSlider;

namespace chaplygin::ui {

class NumberField;

/// The parameters dock: the system, a number field (widgets/number_field) and a slider per
/// parameter (units in the tooltips), the derived m_eff, a, b and I, the speed mode and v_T or v_s.
/// Every edit emits sceneEdited with the whole new scene; the owner validates it and pushes an undo
/// step.
class ParametersPanel : public QWidget {
    Q_OBJECT
  public:
    explicit ParametersPanel(QWidget* parent = nullptr);

    /// Shows a scene without emitting sceneEdited.
    void setScene(const Scene& scene);
    /// The derived m_eff, a, b and I of the solved scene (the document derived them once);
    /// null: the system typed is refused.
    void showDerived(const DerivedSystem* system);
    /// Shows an error under the parameters (empty clears it).
    void showError(const QString& message);
    QString errorText() const;
    /// Whether the parameter's spin box is marked invalid (its value was refused).
    bool isMarkedInvalid(const QString& name) const;

    /// The number field of a parameter ("m", "a", "b", ..., or "speed"), or null.
    NumberField* spinBox(const QString& name) const;
    QSlider* slider(const QString& name) const;

  signals:
    /// description names the change for the undo stack; edits with the same mergeKey merge.
    void sceneEdited(const Scene& scene, const QString& description, const QString& mergeKey);

  private:
    struct Row {
        NumberField* spin = nullptr;
        QSlider* slider = nullptr;
    };
    void rebuildRows();
    /// name: the key ("m", ..., "speed"); the caption, unit, range and words from the table.
    Row addRow(const QString& name, const SystemParameter& parameter, double value);
    void onValueChanged(const QString& name, double value);
    void onSystemChosen(int index);
    void onGyrationChosen(int index);
    void onModeChosen(int index);
    void emitEdit(const QString& description, const QString& mergeKey);

    Scene m_scene;
    bool m_updating = false;
    bool m_shown = false; // whether setScene has shown a scene
    QComboBox* m_system;
    QComboBox* m_gyration;
    QLabel* m_gyrationLabel;
    QFormLayout* m_form;
    QWidget* m_rowsHost;
    QLabel* m_derived;
    QComboBox* m_mode;
    QLabel* m_speedLabel;
    QLabel* m_error;
    std::map<QString, Row> m_rows;
    QString m_lastEdited; // the parameter of the last edit, marked when it is refused
};

} // namespace chaplygin::ui
