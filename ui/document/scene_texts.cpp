#include "document/scene_texts.h"

#include <QCoreApplication>

namespace chaplygin::ui {

QString sceneText(const std::string& english) {
    if (english.empty())
        return {};
    return QCoreApplication::translate("SceneTexts", english.c_str());
}

} // namespace chaplygin::ui
