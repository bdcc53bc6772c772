#pragma once
#include "scene/scene.h"

#include <QWidget>

class QCheckBox;
class QLabel;
class QSlider;

namespace chaplygin::ui {

class NumberField;

/// The Perturbation dock (docs/physics.md §9): whether the scene has perturbed bodies, their
/// offsets, the push, the feedback rate P, the optional |Psidot| limit and the controller's b.
/// Each change is emitted as a whole scene (one undo step; a slider drag merges).
class PerturbationPanel : public QWidget {
    Q_OBJECT
  public:
    explicit PerturbationPanel(QWidget* parent = nullptr);

    /// Shows the scene's perturbation without emitting edits.
    void setScene(const Scene& scene);
    /// The message of a perturbation the scene refuses, empty to clear it.
    void showError(const QString& message);

    QCheckBox* enabledBox() const { return m_enabled; }
    NumberField* spin(const QString& field) const;
    QSlider* rateSlider() const { return m_rateSlider; }
    QCheckBox* pushBox() const { return m_push; }
    QCheckBox* limitBox() const { return m_limit; }
    QCheckBox* controllerBBox() const { return m_controllerB; }

  signals:
    void sceneEdited(const Scene& scene, const QString& description, const QString& mergeKey);

  private:
    /// A field named as the core names it; its domain is the core's (setPerturbationField).
    NumberField* addSpin(const QString& field, double zeroStep, const QString& unit);
    /// The perturbation as the widgets show it.
    Perturbation fromWidgets() const;
    void emitEdit(const QString& description, const QString& mergeKey = {});
    void updateEnabled();

    Scene m_scene;
    bool m_updating = false;
    QCheckBox* m_enabled;
    QCheckBox* m_push;
    QCheckBox* m_limit;
    QCheckBox* m_controllerB;
    QSlider* m_rateSlider;
    QLabel* m_error;
    QWidget* m_fields;
    std::vector<std::pair<QString, NumberField*>> m_spins;
};

} // namespace chaplygin::ui
