#pragma once
#include <QFont>
#include <QPaintDevice>
#include <QString>

#include <initializer_list>

namespace chaplygin::ui {

/// A legend entry's text for its room [px] in the font on the device: the first of its forms
/// (longest first) that fits, else the last (the shortest that is not empty) elided. A narrow
/// canvas in presentation type shows "controlled body" whole rather than "controlled body (tracks
/// the pa…".
QString fittingLegendText(const QFont& font, const QPaintDevice* device, double room,
                          std::initializer_list<QString> forms);

} // namespace chaplygin::ui
