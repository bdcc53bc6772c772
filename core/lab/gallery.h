#pragma once
// The gallery: the scenes where a method or a model fails, read from resources/scenes/gallery
// (docs/numerics.md §4).
#include "scene/lecture.h"
#include "scene/scene.h"

#include <string>
#include <vector>

namespace chaplygin {

/// A scene where a method or a model fails, with what a lecturer should say about it
/// ("where methods fail"), read from resources/scenes/gallery. Each has a test that the failure
/// is detected or handled. What the lecturer says is the scene's note (Markdown).
struct GalleryEntry {
    std::string name;      ///< short id, e.g. "cusp"
    std::string title;     ///< one line for menus
    Scene scene;           ///< scene.note explains the entry (one paragraph)
    bool rejected = false; ///< the app refuses this scene with a message (the failure detected)
    std::string message;   ///< words the refusal contains
};

const std::vector<GalleryEntry>& galleryEntries();
/// Throws InputError for unknown names.
const GalleryEntry& galleryEntry(const std::string& name);

/// The gallery as a lecture (the one Page Down steps through when no lecture is open): the
/// entries the app runs, in the gallery's order, each titled as in the menu; the refused ones
/// are lessons of their own, in the menu only.
Lecture galleryLecture();

} // namespace chaplygin
