#pragma once
#include <QString>

namespace chaplygin {
class InputError;
}

namespace chaplygin::ui {

/// Why the latest scene was refused: the part of the scene at fault (the panel that shows the
/// message beside its fields chooses by it), the place the core named (InputError::where) and
/// the whole message. Empty when the scene solved.
struct SceneError {
    enum class Part {
        None,         ///< no error
        Path,         ///< the path: its expression, range, points, corners
        System,       ///< the system and its parameters, the mode and speed
        Perturbation, ///< the perturbation's fields (docs/physics.md §9)
        Other,        ///< anything else (an internal error)
    };
    Part part = Part::None;
    QString where;
    QString message;

    bool isEmpty() const { return message.isEmpty(); }
    /// The part the core's place names: "perturbation push_dy" is the perturbation's,
    /// "parameter b" the system's, "x = 0.3" or "points" the path's.
    static SceneError of(const InputError& e);
    /// The path worker's refusal of a path (its message names the place).
    static SceneError ofPath(const QString& message);
    /// An error of no field (a failure that is not the input's).
    static SceneError other(const QString& message);
    bool operator==(const SceneError&) const = default;
};

} // namespace chaplygin::ui
