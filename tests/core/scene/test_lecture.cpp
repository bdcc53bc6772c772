// Lecture files: every gallery scene and preset through a lecture and back, and broken lectures
// refused with the scene's index and the field named.
#include "common/atomic_file.h"
#include "common/input_error.h"
#include "lab/gallery.h"
#include "scene/lecture.h"
#include "scene/presets.h"
#include "scene/scene_json.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

using namespace chaplygin;

namespace {

std::string errorOf(const std::string& text) {
    try {
        lectureFromJson(text);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

Lecture everyScene() {
    Lecture l;
    l.title = "Everything, in \u00e9 order";
    for (const GalleryEntry& e : galleryEntries())
        l.entries.push_back({e.title, e.scene});
    for (const std::string& name : presetNames())
        l.entries.push_back({"", presetScene(name)});
    return l;
}

// a small lecture of three presets, as text to break
std::string threeScenes() {
    Lecture l;
    l.title = "Three";
    for (const char* name : {"sinusoid", "circle", "catenary"})
        l.entries.push_back({name, presetScene(name)});
    return lectureToJson(l);
}

} // namespace

TEST(Lecture, EveryGallerySceneAndPresetRoundTrips) {
    const Lecture l = everyScene();
    ASSERT_EQ(l.entries.size(), galleryEntries().size() + presetNames().size());
    const Lecture back = lectureFromJson(lectureToJson(l));
    ASSERT_EQ(back.entries.size(), l.entries.size());
    EXPECT_EQ(back.title, l.title);
    for (std::size_t i = 0; i < l.entries.size(); ++i) {
        EXPECT_EQ(back.entries[i].scene, l.entries[i].scene) << i;
        EXPECT_EQ(back.entries[i].title, l.entries[i].title) << i;
    }
    // the gallery's scenes keep their notes and arrows, what the lecturer shows with them
    for (std::size_t i = 0; i < galleryEntries().size(); ++i) {
        EXPECT_FALSE(back.entries[i].scene.note.empty()) << i;
        EXPECT_EQ(back.entries[i].scene.vectors, galleryEntries()[i].scene.vectors) << i;
    }
    EXPECT_EQ(back, l);
}

TEST(Lecture, ItsScenesAreSceneFilesObjects) {
    // each element of "scenes" is what File > Save writes for that scene, with its title
    const Lecture l = everyScene();
    const nlohmann::json j = nlohmann::json::parse(lectureToJson(l));
    EXPECT_EQ(j.at("format"), "chaplygin-lab-lecture");
    EXPECT_EQ(j.at("version"), 1);
    ASSERT_EQ(j.at("scenes").size(), l.entries.size());
    for (std::size_t i = 0; i < l.entries.size(); ++i) {
        nlohmann::json scene = j.at("scenes")[i];
        if (!l.entries[i].title.empty()) {
            EXPECT_EQ(scene.at("title"), l.entries[i].title) << i;
        }
        scene.erase("title");
        EXPECT_EQ(scene, nlohmann::json::parse(sceneToJson(l.entries[i].scene))) << i;
    }
}

TEST(Lecture, AnEmptyLectureRoundTrips) {
    const Lecture empty;
    EXPECT_EQ(lectureFromJson(lectureToJson(empty)), empty);
}

TEST(Lecture, WrittenWholeAndReadBack) {
    const auto dir = std::filesystem::temp_directory_path() / "chaplygin-lecture-test";
    std::filesystem::create_directories(dir);
    const std::string path = (dir / "lesson.json").string();
    const Lecture l = everyScene();
    saveLectureFile(path, l);
    EXPECT_EQ(loadLectureFile(path), l);
    // a failed write leaves the old file as it was
    EXPECT_THROW(saveLectureFile((dir / "missing" / "lesson.json").string(), l), IoError);
    EXPECT_EQ(loadLectureFile(path), l);
    EXPECT_THROW(loadLectureFile((dir / "absent.json").string()), InputError);
    EXPECT_THROW(loadLectureFile(dir.string()), InputError); // a directory
    std::filesystem::remove_all(dir);
}

TEST(Lecture, TellsALectureFromAScene) {
    EXPECT_TRUE(isLectureText(threeScenes()));
    EXPECT_FALSE(isLectureText(sceneToJson(presetScene("circle"))));
    EXPECT_FALSE(isLectureText(""));
    EXPECT_FALSE(isLectureText("[1, 2]"));
    EXPECT_FALSE(isLectureText(threeScenes().substr(0, 100)));
    EXPECT_FALSE(isLectureText(std::string("\0\1\2", 3)));
}

TEST(Lecture, BrokenFilesAreRefusedWithTheirPlace) {
    const std::string good = threeScenes();
    ASSERT_EQ(lectureFromJson(good).entries.size(), 3u);
    EXPECT_NE(errorOf("").find("lecture file /: the file is empty"), std::string::npos);
    EXPECT_NE(errorOf(good.substr(0, good.size() / 2)).find("lecture file, byte"),
              std::string::npos)
        << errorOf(good.substr(0, good.size() / 2));
    EXPECT_NE(errorOf(good.substr(0, good.size() / 2)).find("not valid JSON"), std::string::npos);
    EXPECT_NE(errorOf("\xEF\xBB\xBF" + good).find("byte-order mark"), std::string::npos);
    EXPECT_NE(errorOf(std::string("{\"a\":\0}", 7)).find("NUL"), std::string::npos);
    EXPECT_NE(errorOf(std::string(100, '[') + std::string(100, ']')).find("nested deeper"),
              std::string::npos);
    EXPECT_NE(errorOf("[1,2]").find("lecture file /: must be an object"), std::string::npos);
    EXPECT_NE(errorOf("{\"version\": 1e400}").find("lecture file"), std::string::npos);

    // a scene file is not a lecture
    EXPECT_NE(errorOf(sceneToJson(presetScene("circle")))
                  .find("lecture file /format: must be \"chaplygin-lab-lecture\""),
              std::string::npos)
        << errorOf(sceneToJson(presetScene("circle")));
    std::string s = good;
    s.replace(s.rfind("\"version\": 1"), 12, "\"version\": 2"); // the lecture's, after its scenes
    EXPECT_NE(errorOf(s).find("lecture file /version: the file is version 2"), std::string::npos)
        << errorOf(s);
    s = good;
    s.replace(s.find("\"scenes\": ["), 11, "\"scenes\": 3, \"x\": [");
    EXPECT_NE(errorOf(s).find("lecture file /scenes: must be an array"), std::string::npos)
        << errorOf(s);
    s = good;
    s.replace(s.find("\"title\": \"Three\""), 16, "\"title\": 3");
    EXPECT_NE(errorOf(s).find("lecture file /title: must be a string"), std::string::npos)
        << errorOf(s);
}

TEST(Lecture, ABadSceneIsNamedByItsIndexAndField) {
    nlohmann::json j = nlohmann::json::parse(threeScenes());
    nlohmann::json bad = j;
    bad["scenes"][2]["speed"] = "fast";
    EXPECT_NE(errorOf(bad.dump()).find("lecture file /scenes/2/speed: must be a number"),
              std::string::npos)
        << errorOf(bad.dump());
    bad = j;
    bad["scenes"][1]["system"]["params"]["m"] = "heavy";
    EXPECT_NE(errorOf(bad.dump()).find("lecture file /scenes/1/system/params/m: must be a number"),
              std::string::npos)
        << errorOf(bad.dump());
    bad = j;
    bad["scenes"][1].erase("system");
    EXPECT_NE(errorOf(bad.dump()).find("lecture file /scenes/1: missing \"system\""),
              std::string::npos)
        << errorOf(bad.dump());
    bad = j;
    bad["scenes"][0]["format"] = "chaplygin-lab-lecture";
    EXPECT_NE(errorOf(bad.dump()).find("lecture file /scenes/0/format"), std::string::npos)
        << errorOf(bad.dump());
    bad = j;
    bad["scenes"][2] = 7;
    EXPECT_NE(errorOf(bad.dump()).find("lecture file /scenes/2: must be a scene object"),
              std::string::npos)
        << errorOf(bad.dump());
    bad = j;
    bad["scenes"][1]["title"] = std::string(kMaxLectureTitleBytes + 1, 'x');
    EXPECT_NE(errorOf(bad.dump()).find("lecture file /scenes/1/title: is 1001 bytes"),
              std::string::npos)
        << errorOf(bad.dump());
    bad = j;
    bad["scenes"][0]["note"] = std::string(kMaxNoteBytes + 1, 'x');
    EXPECT_NE(errorOf(bad.dump()).find("lecture file /scenes/0/note: is 100001 bytes"),
              std::string::npos)
        << errorOf(bad.dump());
}

TEST(Lecture, TooManyScenesOrTooLargeIsRefused) {
    nlohmann::json j = nlohmann::json::parse(threeScenes());
    const nlohmann::json one = j["scenes"][0];
    j["scenes"] = nlohmann::json::array();
    for (std::size_t i = 0; i < kMaxLectureScenes; ++i)
        j["scenes"].push_back(one);
    EXPECT_EQ(lectureFromJson(j.dump()).entries.size(), kMaxLectureScenes);
    j["scenes"].push_back(one);
    EXPECT_NE(errorOf(j.dump()).find("lecture file /scenes: has 501 scenes; a lecture has at most "
                                     "500"),
              std::string::npos)
        << errorOf(j.dump());
    std::string huge = threeScenes();
    huge.insert(1, std::string(kMaxLectureFileBytes, ' '));
    EXPECT_NE(errorOf(huge).find("a lecture is at most 16777216 bytes"), std::string::npos);
}

TEST(Lecture, TheGalleryIsALectureOfTheScenesTheAppRuns) {
    const Lecture g = galleryLecture();
    std::vector<const GalleryEntry*> run;
    for (const GalleryEntry& e : galleryEntries())
        if (!e.rejected)
            run.push_back(&e);
    ASSERT_EQ(g.entries.size(), run.size());
    ASSERT_GE(g.entries.size(), 10u);
    for (std::size_t i = 0; i < run.size(); ++i) {
        EXPECT_EQ(g.entries[i].title, run[i]->title);
        EXPECT_EQ(g.entries[i].scene, run[i]->scene);
    }
    EXPECT_EQ(lectureFromJson(lectureToJson(g)), g);
}

TEST(Lecture, ReadAsASceneItSaysItIsALecture) {
    // --scene and --screenshot read scene files; a lecture given there is named as one
    try {
        sceneFromJson(threeScenes());
        FAIL() << "a lecture read as a scene";
    } catch (const InputError& e) {
        EXPECT_EQ(e.where(), "scene file /format");
        EXPECT_NE(std::string(e.what()).find("is a lecture"), std::string::npos) << e.what();
    }
}
