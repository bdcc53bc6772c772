#include "document/scene_error.h"

#include "common/input_error.h"

#include <QStringList>

namespace chaplygin::ui {

SceneError SceneError::of(const InputError& e) {
    const QString where = QString::fromStdString(e.where());
    const QString first = where.section(QLatin1Char(' '), 0, 0);
    static const QStringList system{QStringLiteral("parameter"), QStringLiteral("system"),
                                    QStringLiteral("mode"), QStringLiteral("speed"),
                                    QStringLiteral("t_end")};
    Part part = Part::Path;
    if (first == QLatin1String("perturbation"))
        part = Part::Perturbation;
    else if (first == QLatin1String("plan")) // the Plan tool's (docs/physics.md §10)
        part = Part::Other;
    else if (system.contains(first))
        part = Part::System;
    return {part, where, QString::fromStdString(e.what())};
}

SceneError SceneError::ofPath(const QString& message) {
    return {Part::Path, QStringLiteral("path"), message};
}

SceneError SceneError::other(const QString& message) {
    return {Part::Other, QString(), message};
}

} // namespace chaplygin::ui
