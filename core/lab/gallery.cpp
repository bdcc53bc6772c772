#include "lab/gallery.h"

#include "common/input_error.h"
#include "scene/scene_json.h"
#include "scene/scene_resources.h"

#include <nlohmann/json.hpp>

#include <stdexcept>

namespace chaplygin {
namespace {

// resources/scenes/gallery/NAME.json: a scene file whose note explains the entry, with a "gallery"
// object (title, rejected, message)
std::vector<GalleryEntry> build() {
    std::vector<GalleryEntry> g;
    const std::string_view folder = "gallery/", suffix = ".json";
    for (const SceneResource& file : sceneResources()) {
        if (!file.path.starts_with(folder) || !file.path.ends_with(suffix))
            continue;
        std::string text(file.text);
        GalleryEntry e;
        e.name = std::string(
            file.path.substr(folder.size(), file.path.size() - folder.size() - suffix.size()));
        try {
            e.scene = sceneFromJson(text);
            const nlohmann::json about = nlohmann::json::parse(text).at("gallery");
            e.title = about.at("title").get<std::string>();
            e.rejected = about.value("rejected", false);
            e.message = about.value("message", std::string());
        } catch (const std::exception& err) {
            // a resource compiled into the program: a build defect, not bad input
            throw std::logic_error("resources/scenes/" + std::string(file.path) + ": " +
                                   err.what());
        }
        g.push_back(std::move(e));
    }
    return g;
}

} // namespace

const std::vector<GalleryEntry>& galleryEntries() {
    static const std::vector<GalleryEntry> entries = build();
    return entries;
}

const GalleryEntry& galleryEntry(const std::string& name) {
    for (const GalleryEntry& e : galleryEntries())
        if (e.name == name)
            return e;
    throw InputError("gallery", "unknown gallery scene '" + name + "'");
}

Lecture galleryLecture() {
    Lecture lecture;
    lecture.title = "Gallery";
    for (const GalleryEntry& e : galleryEntries())
        if (!e.rejected)
            lecture.entries.push_back({e.title, e.scene});
    return lecture;
}

} // namespace chaplygin
