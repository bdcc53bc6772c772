#include "runtime_directory.h"

#include <QDir>
#include <QFile>
#include <QString>

#include <unistd.h>

namespace chaplygin::app {

void ensureRuntimeDirectory() {
    if (!qEnvironmentVariableIsEmpty("XDG_RUNTIME_DIR"))
        return;
    QString runtime =
        QDir::tempPath() + QStringLiteral("/chaplygin-lab-runtime-") + QString::number(::getuid());
    QDir().mkpath(runtime);
    QFile::setPermissions(runtime, QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
    qputenv("XDG_RUNTIME_DIR", runtime.toUtf8());
}

} // namespace chaplygin::app
