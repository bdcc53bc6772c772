#pragma once

#include "shell/language_menu.h"

#include <QString>
#include <QStringList>

class QCoreApplication;
class QLocale;

namespace chaplygin::app {

/// Installs Qt's own translation and Chaplygin Lab's catalogue for the locale's UI languages (e.g.
/// pt_BR), taken from the first of `directories` that holds one. Returns the catalogue's file, or
/// an empty string when none was found; English needs none.
QString installTranslations(QCoreApplication& app, const QLocale& locale,
                            const QStringList& directories = ui::catalogueDirectories());

} // namespace chaplygin::app
