#include "shell/language_menu.h"

#include <QActionGroup>
#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QSettings>

namespace chaplygin::ui {

namespace {
const char* const kLanguageKey = "language";
} // namespace

QString savedLanguage() {
    return QSettings().value(QLatin1String(kLanguageKey)).toString();
}

void saveLanguage(const QString& code) {
    QSettings().setValue(QLatin1String(kLanguageKey), code);
}

QStringList catalogueDirectories() {
    const QDir bin(QCoreApplication::applicationDirPath());
    return {QDir::cleanPath(bin.filePath(QStringLiteral("../share/chaplygin-lab/translations"))),
            QStringLiteral(":/i18n")};
}

bool catalogueAvailable(const QString& code, const QStringList& directories) {
    if (code.isEmpty() || code == QLatin1String("en"))
        return true;
    const QString file = QStringLiteral("chaplygin-lab_%1.qm").arg(code);
    for (const QString& directory : directories)
        if (QFileInfo::exists(QDir(directory).filePath(file)))
            return true;
    return false;
}

QLocale languageLocale(const QString& code) {
    return code.isEmpty() ? QLocale::system() : QLocale(code);
}

LanguageMenu::LanguageMenu(QWidget* parent, const QStringList& directories)
    : QMenu(tr("&Language"), parent) {
    setObjectName(QStringLiteral("languageMenu"));
    auto* group = new QActionGroup(this);
    const QString saved = savedLanguage();
    struct Choice {
        QString code, name;
    };
    // each language by its own name, so that a reader of neither finds theirs
    const Choice choices[] = {{QString(), tr("System")},
                              {QStringLiteral("en"), QStringLiteral("English")},
                              {QStringLiteral("pt_BR"), QStringLiteral("Portugu\u00eas (Brasil)")}};
    for (const Choice& c : choices) {
        QAction* action = addAction(c.name);
        action->setCheckable(true);
        action->setChecked(c.code == saved);
        action->setData(c.code);
        action->setStatusTip(tr("Takes effect at the next start of Chaplygin Lab"));
        if (!catalogueAvailable(c.code, directories)) {
            action->setEnabled(false);
            action->setText(tr("%1 (not installed)").arg(c.name));
            action->setStatusTip(tr("The catalogue of this language is not installed"));
        }
        group->addAction(action);
        connect(action, &QAction::triggered, this, [code = c.code] { saveLanguage(code); });
    }
    addSeparator();
    addAction(tr("Takes effect at the next start"))->setEnabled(false);
}

} // namespace chaplygin::ui
