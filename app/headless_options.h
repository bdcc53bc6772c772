#pragma once
#include "common/input_error.h"
#include "lab/parameter_sweep.h"
#include "planning/pose_planner.h"
#include "scene/scene.h"

#include <optional>
#include <string>
#include <vector>

namespace chaplygin {

namespace app {
class OptionValues;
}

/// The parsed headless command line (chaplygin-lab --headless --help).
struct HeadlessOptions {
    Scene scene;
    std::optional<std::vector<double>> times; ///< --times: rows exactly at these times
    int samples = 501;                        ///< --samples: rows evenly spaced on [0, t_end]
    std::string csvPath, summaryPath, plotsDir;
    std::vector<std::string> formats{"png"};
    bool help = false;
    bool workPrecision = false;     ///< --work-precision: the speed-against-accuracy sweep
    std::optional<SweepSpec> sweep; ///< --sweep NAME=FROM:TO:COUNT
    std::string animationPath;      ///< --animation FILE: GIF, MP4 or a folder of PNG frames
    int fps = 30;                   ///< --fps
    int width = 1280, height = 720; ///< --size WxH of the animation
    bool withPlots = false;         ///< --with-plots: the plots beside the canvas
    std::string body = "auto";      ///< --body auto|scale|outline|marker in the animation
    std::optional<Pose> planTo;     ///< --plan-to X,Y,PHI: plan the genuine vakonomic motions
    std::optional<Pose> planFrom;   ///< --plan-from X,Y,PHI (default: the path's start, or 0)
    double planHorizon = 0;         ///< --plan-horizon T [s]; 0: the planner's default
    int planChoice = 0;             ///< --plan-choice N: the CSV's motion, 1 = first listed
    bool trackPlan = false;         ///< --track-plan: the chosen motion's track is the path
    bool link = false;              ///< --link: print the scene's link and nothing else
    bool pathGiven = false;         ///< --preset, --scene, --path or --points was given
};

/// Parses the arguments after --headless (and the scene options the screenshot mode shares).
/// Throws InputError naming the option and what is wrong with it.
HeadlessOptions parseHeadlessOptions(const std::vector<std::string>& args);

/// Checks the value of --body (auto, scale, outline or marker, the screenshot's and the
/// animation's); throws InputError("--body") naming the value otherwise.
void checkBodyOption(const std::string& value);

/// Parses a whole string as a finite double; throws InputError(where) otherwise.
double parseNumber(const std::string& text, const std::string& where);

/// Parses --sweep NAME=FROM:TO:COUNT; throws InputError("--sweep").
SweepSpec parseSweepSpec(const std::string& text);
/// The same error with the command-line option in place of the scene field the core names
/// (speed -> --vT or --vs by the mode, t_end -> --t-end, preset, system, mode, corners,
/// scene_file); other errors are returned unchanged.
InputError withOptionNames(const InputError& error, SpeedMode mode);

/// The scene that --preset, --scene, --path or --points and the system and motion options
/// describe (the window, the screenshot and the headless run share them). Throws InputError.
Scene sceneFromOptions(const app::OptionValues& given);

} // namespace chaplygin
