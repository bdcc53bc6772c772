#pragma once
// The words of the scene files the window shows (gallery titles and notes, the presets' names and
// descriptions) in the user's language: the English of resources/scenes is the key, the
// translation lives in the catalogue under the context SceneTexts (lupdate reads the scene files
// through resources/translations/CMakeLists.txt).
#include <QString>

#include <string>

namespace chaplygin::ui {

/// The translation of a text of a scene file; a text without one (a note the user wrote) is
/// returned as it is.
QString sceneText(const std::string& english);

} // namespace chaplygin::ui
