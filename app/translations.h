#pragma once

#include <QString>
#include <QStringList>

class QCoreApplication;
class QLocale;

namespace chaplygin::app {

/// Where Chaplygin Lab's catalogues are looked for, in order: share/chaplygin-lab/translations of
/// the program's installation prefix (installed beside bin/, so a distribution can update it
/// without a rebuild), then the catalogue compiled in under :/i18n (resources/translations/), which
/// serves a program run from its build tree.
QStringList catalogueDirectories();

/// Installs Qt's own translation and Chaplygin Lab's catalogue for the locale's UI languages (e.g.
/// pt_BR), taken from the first of `directories` that holds one. Returns the catalogue's file, or
/// an empty string when none was found; English needs none.
QString installTranslations(QCoreApplication& app, const QLocale& locale,
                            const QStringList& directories = catalogueDirectories());

} // namespace chaplygin::app
