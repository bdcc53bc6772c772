#include "document/file_dialogs.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QRegularExpression>
#include <QSettings>
#include <QStandardPaths>

#include <algorithm>

namespace chaplygin::ui {

namespace {

DialogHook& hook() {
    static DialogHook h;
    return h;
}

// the patterns of a filter "Scenes (*.json *.JSON)": {"*.json", "*.JSON"}
QStringList patterns(const QString& filter) {
    static const QRegularExpression inParens(QStringLiteral("\\(([^)]*)\\)"));
    QRegularExpressionMatch m = inParens.match(filter);
    if (!m.hasMatch())
        return {};
    return m.captured(1).split(QLatin1Char(' '), Qt::SkipEmptyParts);
}

QString firstFilter(const QString& filters) {
    return filters.section(QStringLiteral(";;"), 0, 0);
}

} // namespace

QString withFilterExtension(const QString& path, const QString& selectedFilter) {
    if (path.isEmpty())
        return path;
    const QStringList ps = patterns(selectedFilter);
    QString first;
    for (const QString& p : ps) {
        if (!p.startsWith(QLatin1String("*.")) || p.indexOf(QLatin1Char('*'), 1) >= 0)
            continue;
        QString ext = p.mid(1); // ".json"
        if (path.endsWith(ext, Qt::CaseInsensitive))
            return path;
        if (first.isEmpty())
            first = ext;
    }
    if (first.isEmpty()) // "*" or no patterns: the user's name stands
        return path;
    return path + first;
}

QString sceneFileStem(const Scene& scene, const QString& fileName) {
    QString stem;
    if (!fileName.isEmpty())
        stem = QFileInfo(fileName).completeBaseName();
    else if (!scene.preset.empty())
        stem = QString::fromStdString(scene.preset);
    else
        switch (scene.path.kind) {
        case PathKind::Graph:
            stem = QStringLiteral("graph-") + QString::fromStdString(scene.path.y);
            break;
        case PathKind::Parametric:
            stem = QStringLiteral("parametric");
            break;
        default:
            stem = QStringLiteral("drawn");
            break;
        }
    static const QRegularExpression unsafe(QStringLiteral("[^A-Za-z0-9_]+"));
    stem.replace(unsafe, QStringLiteral("-"));
    while (stem.endsWith(QLatin1Char('-')))
        stem.chop(1);
    while (stem.startsWith(QLatin1Char('-')))
        stem.remove(0, 1);
    stem = stem.left(48);
    return stem.isEmpty() ? QStringLiteral("scene") : stem;
}

QString lastFolder(const QString& purpose) {
    QSettings settings;
    const QString dir = settings.value(QStringLiteral("dialogs/") + purpose).toString();
    if (!dir.isEmpty() && QFileInfo(dir).isDir())
        return dir;
    // a kind not used yet, or its folder moved or deleted since: the last one used for anything
    const QString last = settings.value(QStringLiteral("dialogs/last")).toString();
    if (!last.isEmpty() && QFileInfo(last).isDir())
        return last;
    const QString docs = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    return !docs.isEmpty() && QFileInfo(docs).isDir() ? docs : QDir::homePath();
}

void rememberFolder(const QString& purpose, const QString& fileOrFolder) {
    if (fileOrFolder.isEmpty())
        return;
    QFileInfo info(fileOrFolder);
    QString dir = info.isDir() ? info.absoluteFilePath() : info.absolutePath();
    QSettings settings;
    settings.setValue(QStringLiteral("dialogs/") + purpose, dir);
    settings.setValue(QStringLiteral("dialogs/last"), dir);
}

void setDialogHook(DialogHook h) {
    hook() = std::move(h);
}

QString chooseSaveFile(QWidget* parent, const QString& caption, const QString& purpose,
                       const QString& stem, const QString& filters) {
    QString first = firstFilter(filters);
    QString proposed = withFilterExtension(QDir(lastFolder(purpose)).filePath(stem), first);
    DialogChoice choice;
    if (hook()) {
        choice = hook()(caption, proposed, filters);
    } else {
        choice.filter = first;
        choice.path =
            QFileDialog::getSaveFileName(parent, caption, proposed, filters, &choice.filter);
    }
    if (choice.path.isEmpty())
        return {};
    QString path =
        withFilterExtension(choice.path, choice.filter.isEmpty() ? first : choice.filter);
    rememberFolder(purpose, path);
    return path;
}

QString chooseOpenFile(QWidget* parent, const QString& caption, const QString& purpose,
                       const QString& filters) {
    QString path =
        hook() ? hook()(caption, lastFolder(purpose), filters).path
               : QFileDialog::getOpenFileName(parent, caption, lastFolder(purpose), filters);
    rememberFolder(purpose, path);
    return path;
}

QString chooseFolder(QWidget* parent, const QString& caption, const QString& purpose) {
    QString dir = hook() ? hook()(caption, lastFolder(purpose), {}).path
                         : QFileDialog::getExistingDirectory(parent, caption, lastFolder(purpose));
    rememberFolder(purpose, dir);
    return dir;
}

QString askForText(QWidget* parent, const QString& caption, const QString& label,
                   const QString& proposed) {
    if (hook())
        return hook()(caption, proposed, {}).path;
    QInputDialog dialog(parent);
    dialog.setWindowTitle(caption);
    dialog.setLabelText(label);
    dialog.setTextValue(proposed);
    // some seventy characters: enough to see that it is a link and where it ends being one
    dialog.resize(std::max(dialog.sizeHint().width(), dialog.fontMetrics().averageCharWidth() * 70),
                  dialog.sizeHint().height());
    return dialog.exec() == QDialog::Accepted ? dialog.textValue() : QString();
}

} // namespace chaplygin::ui
