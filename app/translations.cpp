#include "translations.h"

#include <QCoreApplication>
#include <QDir>
#include <QLibraryInfo>
#include <QLocale>
#include <QTranslator>

namespace chaplygin::app {

QString installTranslations(QCoreApplication& app, const QLocale& locale,
                            const QStringList& directories) {
    auto* qt = new QTranslator(&app);
    if (qt->load(locale, QStringLiteral("qtbase"), QStringLiteral("_"),
                 QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QCoreApplication::installTranslator(qt);
    else
        delete qt;
    for (const QString& directory : directories) {
        auto* own = new QTranslator(&app);
        if (own->load(locale, QStringLiteral("chaplygin-lab"), QStringLiteral("_"), directory)) {
            QCoreApplication::installTranslator(own);
            return own->filePath();
        }
        delete own;
    }
    return {};
}

} // namespace chaplygin::app
