// Scene links: every preset and gallery scene round-trips bit-exact in under 2,000 characters,
// and a damaged or hostile link is refused with a message naming what is wrong.
#include "common/input_error.h"
#include "scene/scene_json.h"
#include "scene/scene_link.h"
#include "scene/scene_resources.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <chrono>
#include <random>
#include <string>

using namespace chaplygin;

namespace {

// zlib's own compressor and a base64url encoder written here, independent of the link's
std::string zlibCompressed(const std::string& bytes) {
    uLongf size = compressBound(static_cast<uLong>(bytes.size()));
    std::string out(size, '\0');
    EXPECT_EQ(compress2(reinterpret_cast<Bytef*>(out.data()), &size,
                        reinterpret_cast<const Bytef*>(bytes.data()),
                        static_cast<uLong>(bytes.size()), 9),
              Z_OK);
    out.resize(size);
    return out;
}

std::string base64Url(const std::string& bytes) {
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_";
    std::string out;
    unsigned buffer = 0;
    int bits = 0;
    for (unsigned char c : bytes) {
        buffer = (buffer << 8) | c;
        bits += 8;
        while (bits >= 6) {
            bits -= 6;
            out += digits[(buffer >> bits) & 63];
        }
    }
    if (bits > 0)
        out += digits[(buffer << (6 - bits)) & 63];
    return out;
}

std::string linkHolding(const std::string& bytes) {
    return "chaplygin-lab:" + base64Url(zlibCompressed(bytes));
}

std::string refusal(const std::string& link) {
    try {
        sceneFromLink(link);
    } catch (const InputError& e) {
        EXPECT_EQ(e.where().rfind("scene link", 0), 0u) << e.what();
        return e.what();
    }
    return "accepted";
}

std::string lineJson() {
    return std::string(sceneResources()[0].text);
}

} // namespace

TEST(SceneLink, EveryPresetAndGalleryScene_RoundTripsBitExactUnder2000Characters) {
    ASSERT_GE(sceneResources().size(), 18u);
    for (const SceneResource& r : sceneResources()) {
        const Scene scene = sceneFromJson(std::string(r.text));
        const std::string link = sceneToLink(scene);
        EXPECT_EQ(link.rfind("chaplygin-lab:", 0), 0u) << r.path;
        EXPECT_LT(link.size(), 2000u) << r.path;
        const Scene back = sceneFromLink(link);
        EXPECT_EQ(back, scene) << r.path;
        EXPECT_EQ(sceneToJson(back), sceneToJson(scene)) << r.path;
        EXPECT_EQ(link.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                         "0123456789-_",
                                         14),
                  std::string::npos)
            << r.path << ": not URL-safe";
    }
}

TEST(SceneLink, ReadsALinkMadeByAnotherEncoder) {
    // the scene file's text itself, compressed by zlib and encoded here
    for (const SceneResource& r : sceneResources())
        EXPECT_EQ(sceneFromLink(linkHolding(std::string(r.text))),
                  sceneFromJson(std::string(r.text)))
            << r.path;
}

TEST(SceneLink, ToleratesWhiteSpaceAroundPaddingAndTheSchemesCase) {
    const std::string link = linkHolding(lineJson());
    const Scene scene = sceneFromJson(lineJson());
    EXPECT_EQ(sceneFromLink("  " + link + "\n"), scene);
    EXPECT_EQ(sceneFromLink("Chaplygin-Lab:" + link.substr(14)), scene);
    std::string padded = link;
    while ((padded.size() - 14) % 4 != 0)
        padded += '=';
    EXPECT_EQ(sceneFromLink(padded), scene);
}

TEST(SceneLink, EveryTruncation_IsRefusedAsTruncated) {
    const std::string link = sceneToLink(sceneFromJson(lineJson()));
    EXPECT_NE(refusal("chaplygin-lab:").find("nothing follows chaplygin-lab:"), std::string::npos);
    for (std::size_t n = 15; n < link.size(); ++n)
        EXPECT_NE(refusal(link.substr(0, n)).find("truncated"), std::string::npos)
            << n << ": " << refusal(link.substr(0, n));
}

TEST(SceneLink, ACharacterOutsideBase64Url_IsNamedWithItsPosition) {
    const std::string link = sceneToLink(sceneFromJson(lineJson()));
    std::string plus = link;
    plus[20] = '+'; // standard base64, not base64url
    EXPECT_NE(refusal(plus).find("character '+' at position 21 is not base64url"),
              std::string::npos)
        << refusal(plus);
    std::string spaced = link;
    spaced[30] = ' ';
    EXPECT_NE(refusal(spaced).find("a space at position 31"), std::string::npos);
    std::string binary = link;
    binary[40] = '\xC3';
    EXPECT_NE(refusal(binary).find("byte 0xC3 at position 41"), std::string::npos);
}

TEST(SceneLink, AnotherScheme_IsNamed) {
    EXPECT_NE(refusal("https://example.org/scene.json").find("'https:' is another scheme"),
              std::string::npos);
    EXPECT_NE(refusal("mailto:someone@example.org").find("'mailto:' is another scheme"),
              std::string::npos);
    EXPECT_NE(refusal("eJzLSM3JyQcABiwCFQ").find("does not start with chaplygin-lab:"),
              std::string::npos);
}

TEST(SceneLink, ADecompressionBomb_StopsAtTheCapQuickly) {
    // 64 MB of spaces compress to about 64 kB, a link of some 87,000 characters
    const std::string bomb = linkHolding(std::string(64u << 20, ' '));
    ASSERT_LT(bomb.size(), kMaxSceneLinkChars);
    const auto start = std::chrono::steady_clock::now();
    const std::string message = refusal(bomb);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_NE(message.find("inflates to more than 1048576 bytes"), std::string::npos) << message;
    EXPECT_LT(seconds, 0.2);
    // just over the cap, and just under it (which then fails as JSON, not as a bomb)
    EXPECT_NE(refusal(linkHolding(std::string(kMaxSceneLinkBytes + 1, ' ')))
                  .find("inflates to more than"),
              std::string::npos);
    EXPECT_EQ(refusal(linkHolding(std::string(kMaxSceneLinkBytes, ' '))).find("inflates"),
              std::string::npos);
}

TEST(SceneLink, ALinkLongerThanAnArgument_IsRefusedBeforeDecoding) {
    const std::string longLink = "chaplygin-lab:" + std::string(kMaxSceneLinkChars, 'A');
    EXPECT_NE(refusal(longLink).find("characters; a scene link has at most 131072"),
              std::string::npos)
        << refusal(longLink);
}

TEST(SceneLink, DamagedStreams_AreRefused) {
    // not zlib at all
    EXPECT_NE(refusal("chaplygin-lab:" + base64Url("hello, world")).find("damaged"),
              std::string::npos);
    // a flipped byte in the middle: the deflate data or the Adler-32 check fails
    std::string compressed = zlibCompressed(lineJson());
    compressed[compressed.size() / 2] ^= 0x20;
    EXPECT_NE(refusal("chaplygin-lab:" + base64Url(compressed)).find("damaged"), std::string::npos)
        << refusal("chaplygin-lab:" + base64Url(compressed));
    // bytes after the end of the stream
    EXPECT_NE(refusal("chaplygin-lab:" + base64Url(zlibCompressed(lineJson()) + "xyz"))
                  .find("damaged: 3 bytes follow the end"),
              std::string::npos);
    // nothing inside
    EXPECT_NE(refusal(linkHolding("")).find("empty scene"), std::string::npos);
}

TEST(SceneLink, RandomNoise_IsRefusedAndNeverCrashes) {
    std::mt19937 random(28);
    const std::string digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_";
    for (int trial = 0; trial < 2000; ++trial) {
        std::string noise = "chaplygin-lab:";
        const int length = 1 + int(random() % 600);
        for (int i = 0; i < length; ++i)
            noise += trial % 2 ? char(random() % 256) : digits[random() % 64];
        EXPECT_NE(refusal(noise), "accepted") << noise;
    }
}

TEST(SceneLink, TheSceneFilesChecksApplyToWhatALinkHolds) {
    std::string json = lineJson();
    const std::string mass = "\"m\": 1";
    const auto at = json.find(mass);
    ASSERT_NE(at, std::string::npos) << json;
    json.replace(at, mass.size(), "\"m\": \"heavy\", \"x\": 1");
    const std::string message = refusal(linkHolding(json));
    EXPECT_EQ(message.rfind("scene link /system/params/m", 0), 0u) << message;
    EXPECT_NE(refusal(linkHolding("{\"format\": \"chaplygin-lab-scene\", \"version\": 99}"))
                  .find("scene link /version"),
              std::string::npos)
        << refusal(linkHolding("{\"format\": \"chaplygin-lab-scene\", \"version\": 99}"));
    EXPECT_NE(refusal(linkHolding("not json")).find("scene link"), std::string::npos)
        << refusal(linkHolding("not json"));
}

TEST(SceneLink, LoadSceneFileOrLink_TellsLinksFromFilesAndRefusesOtherSchemes) {
    const std::string file = std::string(CHAPLYGIN_SCENE_DIR) + "/presets/line.json";
    const Scene line = loadSceneFile(file);
    EXPECT_EQ(loadSceneFileOrLink(file), line);
    EXPECT_EQ(loadSceneFileOrLink(sceneToLink(line)), line);
    try {
        loadSceneFileOrLink("https://example.org/a.json");
        ADD_FAILURE() << "accepted another scheme";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("'https:' is another scheme"), std::string::npos);
    }
    try {
        loadSceneFileOrLink("/nonexistent/scene.json");
        ADD_FAILURE() << "accepted a missing file";
    } catch (const InputError& e) {
        EXPECT_EQ(e.where(), "scene_file");
    }
}
