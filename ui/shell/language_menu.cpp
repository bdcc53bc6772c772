#include "shell/language_menu.h"

#include <QActionGroup>
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

QLocale languageLocale(const QString& code) {
    return code.isEmpty() ? QLocale::system() : QLocale(code);
}

LanguageMenu::LanguageMenu(QWidget* parent) : QMenu(tr("&Language"), parent) {
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
        group->addAction(action);
        connect(action, &QAction::triggered, this, [code = c.code] { saveLanguage(code); });
    }
    addSeparator();
    addAction(tr("Takes effect at the next start"))->setEnabled(false);
}

} // namespace chaplygin::ui
