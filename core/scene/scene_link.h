#pragma once
// A scene as a link: "chaplygin-lab:" followed by the scene file's JSON, zlib-compressed and
// written in base64url (RFC 4648 §5, no padding), so that it can be pasted into a chat, a course
// page or an e-mail and opened by the program wherever a scene file goes.
#include "scene/scene.h"

#include <cstddef>
#include <string>
#include <string_view>

namespace chaplygin {

/// The scheme every scene link starts with (matched without regard to case, as URI schemes are).
constexpr std::string_view kSceneLinkScheme = "chaplygin-lab:";

/// The longest link read or written, in characters: Linux's limit on one program argument
/// (MAX_ARG_STRLEN), so that every link made can be given on a command line.
constexpr std::size_t kMaxSceneLinkChars = 131072;

/// The most a link may inflate to, in bytes: reading stops there, so a decompression bomb costs
/// at most this much memory and the time to inflate it.
constexpr std::size_t kMaxSceneLinkBytes = 1u << 20;

/// The scene as a link, without the pen's marks (Scene::annotations): a link of a scene file
/// saved with them is the link of the scene. Throws InputError("scene link") when its JSON is
/// longer than kMaxSceneLinkBytes or the link longer than kMaxSceneLinkChars (share the file
/// instead).
std::string sceneToLink(const Scene& scene);

/// The scene a link holds. Throws InputError whose where() is "scene link" and whose message
/// names what is wrong (another scheme, a character that is not base64url, a truncated or
/// damaged stream, more than kMaxSceneLinkBytes inflated), or "scene link" plus the JSON path
/// when the scene inside fails the scene file's checks. Surrounding white space is ignored.
Scene sceneFromLink(std::string_view link);

/// Whether text starts with the scene link's scheme (after any leading white space).
bool isSceneLink(std::string_view text);

/// Whether loadSceneFileOrLink reads the text as a link: a scene link, or text that starts with
/// another URI scheme and names no file.
bool readsAsLink(const std::string& fileOrLink);

/// A scene file's path or a scene link, as --scene and the window's argument take them: a link is
/// read with sceneFromLink; text that starts with another URI scheme (two or more letters and a
/// colon, "https:") and names no file is refused, naming the scheme; anything else is a file.
Scene loadSceneFileOrLink(const std::string& fileOrLink);

} // namespace chaplygin
