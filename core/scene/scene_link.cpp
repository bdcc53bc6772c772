#include "scene/scene_link.h"

#include "common/input_error.h"
#include "scene/scene_json.h"

#include <zlib.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <new>
#include <optional>
#include <vector>

namespace chaplygin {
namespace {

constexpr const char* kWhere = "scene link";
constexpr std::string_view kBase64Url =
    "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_";

[[noreturn]] void bad(const std::string& what) {
    throw InputError(kWhere, what);
}

char lower(char c) {
    return c >= 'A' && c <= 'Z' ? char(c - 'A' + 'a') : c;
}

bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}

std::string_view trimmed(std::string_view text) {
    while (!text.empty() && isSpace(text.front()))
        text.remove_prefix(1);
    while (!text.empty() && isSpace(text.back()))
        text.remove_suffix(1);
    return text;
}

bool startsWithScheme(std::string_view text) {
    if (text.size() < kSceneLinkScheme.size())
        return false;
    for (std::size_t i = 0; i < kSceneLinkScheme.size(); ++i)
        if (lower(text[i]) != kSceneLinkScheme[i])
            return false;
    return true;
}

// a URI's scheme, RFC 3986 §3.1: a letter, then letters, digits, '+', '-' or '.', then ':'; at
// least two characters, so that a drive letter "C:" is not one
std::optional<std::string_view> uriScheme(std::string_view text) {
    const auto colon = text.find(':');
    if (colon == std::string_view::npos || colon < 2)
        return std::nullopt;
    const auto isLetter = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); };
    if (!isLetter(text[0]))
        return std::nullopt;
    for (std::size_t i = 1; i < colon; ++i) {
        const char c = text[i];
        if (!isLetter(c) && !(c >= '0' && c <= '9') && c != '+' && c != '-' && c != '.')
            return std::nullopt;
    }
    return text.substr(0, colon + 1);
}

// a character of the link as a message shows it: printable ASCII quoted, anything else as a byte
std::string shown(char c) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte == 0x20)
        return "a space";
    if (byte >= 0x21 && byte < 0x7F)
        return std::string("character '") + c + "'";
    std::array<char, 16> hex{};
    std::snprintf(hex.data(), hex.size(), "byte 0x%02X", byte);
    return hex.data();
}

std::string encodeBase64Url(const std::string& bytes) {
    std::string out;
    out.reserve((bytes.size() * 4 + 2) / 3);
    std::size_t i = 0;
    for (; i + 3 <= bytes.size(); i += 3) {
        const unsigned v = unsigned(static_cast<unsigned char>(bytes[i])) << 16 |
                           unsigned(static_cast<unsigned char>(bytes[i + 1])) << 8 |
                           unsigned(static_cast<unsigned char>(bytes[i + 2]));
        for (int shift : {18, 12, 6, 0})
            out += kBase64Url[(v >> shift) & 63];
    }
    const std::size_t rest = bytes.size() - i;
    if (rest > 0) {
        unsigned v = unsigned(static_cast<unsigned char>(bytes[i])) << 16;
        if (rest == 2)
            v |= unsigned(static_cast<unsigned char>(bytes[i + 1])) << 8;
        out += kBase64Url[(v >> 18) & 63];
        out += kBase64Url[(v >> 12) & 63];
        if (rest == 2)
            out += kBase64Url[(v >> 6) & 63];
    }
    return out;
}

// the payload's bytes; `offset` is the payload's place in the link, for the positions in messages
std::string decodeBase64Url(std::string_view text, std::size_t offset) {
    // padding is not written, but a link that gained it on the way still reads
    std::size_t length = text.size();
    while (length > 0 && text.size() - length < 2 && text[length - 1] == '=')
        --length;
    std::string out;
    out.reserve(length * 3 / 4);
    unsigned buffer = 0;
    int bits = 0;
    for (std::size_t i = 0; i < length; ++i) {
        const auto digit = kBase64Url.find(text[i]);
        if (digit == std::string_view::npos)
            bad(shown(text[i]) + " at position " + std::to_string(offset + i + 1) +
                " is not base64url (A-Z, a-z, 0-9, '-' and '_')");
        buffer = (buffer << 6) | unsigned(digit);
        bits += 6;
        if (bits >= 8) {
            bits -= 8;
            out += char((buffer >> bits) & 0xFF);
        }
    }
    if (length % 4 == 1)
        bad("truncated: " + std::to_string(length) +
            " base64url characters end partway through a byte");
    return out;
}

// the inflater, released on every way out
class Inflater {
  public:
    Inflater() {
        if (inflateInit(&m_stream) != Z_OK)
            throw std::bad_alloc();
    }
    ~Inflater() { inflateEnd(&m_stream); }
    Inflater(const Inflater&) = delete;
    Inflater& operator=(const Inflater&) = delete;
    z_stream& stream() { return m_stream; }

  private:
    z_stream m_stream{};
};

// zlib's stream inflated a buffer at a time, stopping at kMaxSceneLinkBytes
std::string inflateScene(const std::string& compressed) {
    Inflater inflater;
    z_stream& zs = inflater.stream();
    zs.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(compressed.data()));
    zs.avail_in = static_cast<uInt>(compressed.size());
    std::string out;
    std::array<char, 16384> buffer{};
    for (;;) {
        zs.next_out = reinterpret_cast<Bytef*>(buffer.data());
        zs.avail_out = static_cast<uInt>(buffer.size());
        const int status = inflate(&zs, Z_NO_FLUSH);
        const std::size_t produced = buffer.size() - zs.avail_out;
        if (status == Z_MEM_ERROR)
            throw std::bad_alloc();
        if (status == Z_DATA_ERROR || status == Z_NEED_DICT || status == Z_STREAM_ERROR)
            bad(std::string("damaged: not a compressed scene (zlib: ") +
                (zs.msg ? zs.msg : "invalid data") + ")");
        if (out.size() + produced > kMaxSceneLinkBytes)
            bad("it inflates to more than " + std::to_string(kMaxSceneLinkBytes) +
                " bytes, the most a scene link may hold (a decompression bomb?)");
        out.append(buffer.data(), produced);
        if (status == Z_STREAM_END)
            break;
        if (status == Z_BUF_ERROR || (zs.avail_in == 0 && zs.avail_out > 0))
            bad("truncated: the compressed scene stops before its end");
    }
    if (zs.avail_in > 0)
        bad("damaged: " + std::to_string(zs.avail_in) +
            " bytes follow the end of the compressed scene");
    return out;
}

} // namespace

std::string sceneToLink(const Scene& scene) {
    // the pen's marks stay with the file: a link is the scene alone
    Scene plain = scene;
    plain.annotations.clear();
    const std::string json = sceneToJson(plain);
    if (json.size() > kMaxSceneLinkBytes)
        bad("the scene's JSON is " + std::to_string(json.size()) + " bytes; a link holds at most " +
            std::to_string(kMaxSceneLinkBytes) + "; share the scene file instead");
    uLongf size = compressBound(static_cast<uLong>(json.size()));
    std::string compressed(size, '\0');
    const int status = compress2(reinterpret_cast<Bytef*>(compressed.data()), &size,
                                 reinterpret_cast<const Bytef*>(json.data()),
                                 static_cast<uLong>(json.size()), Z_BEST_COMPRESSION);
    if (status == Z_MEM_ERROR)
        throw std::bad_alloc();
    if (status != Z_OK)
        throw std::logic_error("zlib compress2 failed");
    compressed.resize(size);
    std::string link = std::string(kSceneLinkScheme) + encodeBase64Url(compressed);
    if (link.size() > kMaxSceneLinkChars)
        bad("the link would be " + std::to_string(link.size()) + " characters, more than the " +
            std::to_string(kMaxSceneLinkChars) + " a link may have; share the scene file instead");
    return link;
}

Scene sceneFromLink(std::string_view link) {
    link = trimmed(link);
    if (!startsWithScheme(link)) {
        if (auto scheme = uriScheme(link)) {
            std::string message(*scheme);
            message.insert(message.begin(), '\'');
            message += "' is another scheme; a scene link starts with ";
            message += kSceneLinkScheme;
            bad(message);
        }
        bad("does not start with " + std::string(kSceneLinkScheme));
    }
    if (link.size() > kMaxSceneLinkChars)
        bad("the link is " + std::to_string(link.size()) +
            " characters; a scene link has at most " + std::to_string(kMaxSceneLinkChars));
    const std::string_view payload = link.substr(kSceneLinkScheme.size());
    if (payload.empty())
        bad("nothing follows " + std::string(kSceneLinkScheme));
    const std::string json = inflateScene(decodeBase64Url(payload, kSceneLinkScheme.size()));
    if (json.empty())
        bad("it holds an empty scene");
    try {
        return sceneFromJson(json);
    } catch (const InputError& e) {
        // the scene file's checks name a JSON path: here it is the link's
        const std::string& where = e.where();
        const std::string message = e.what();
        const std::string what = message.substr(std::min(message.size(), where.size() + 2));
        const std::string prefix = "scene file";
        const std::string path =
            where.rfind(prefix, 0) == 0 ? where.substr(prefix.size()) : " " + where;
        throw InputError(kWhere + path, what);
    }
}

bool isSceneLink(std::string_view text) {
    return startsWithScheme(trimmed(text));
}

bool readsAsLink(const std::string& fileOrLink) {
    if (isSceneLink(fileOrLink))
        return true;
    std::error_code ignored;
    return uriScheme(fileOrLink) && !std::filesystem::exists(fileOrLink, ignored);
}

Scene loadSceneFileOrLink(const std::string& fileOrLink) {
    // another scheme is refused by sceneFromLink, which names it
    return readsAsLink(fileOrLink) ? sceneFromLink(fileOrLink) : loadSceneFile(fileOrLink);
}

} // namespace chaplygin
