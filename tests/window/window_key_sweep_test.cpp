// Every key of the key table (window::key_help(), which docs/window.md
// lists) on every glTF sample and the showcase, under xvfb-run: the window
// keeps running through all of them (an effect that does not apply to the
// scene or camera keeps the previous one and says why) and ends with Esc,
// exit status 0. Also from an orthographic camera, where the lens,
// curved mirror and non-affine effects cannot be drawn.
#include "process.hpp"

#include "../skips.hpp"

#include "../sample_files.hpp"

#include <doctest/doctest.h>

#include <window/key_help.hpp>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace {

using window_test::Child;

const std::string kDemo = FRUSTUM_DEMO_EXE;

// The table's keys as --keys items: "1..7" -> 1,...,7; "Shift+A D W S" ->
// Shift+A,Shift+D,...; mouse actions ("left drag", "wheel") are skipped;
// Esc is left for the end.
std::vector<std::string> table_keys() {
    std::vector<std::string> keys;
    for (const window::KeyHelp& entry : window::key_help()) {
        std::string text = entry.keys;
        if (const std::size_t dots = text.find(".."); dots != std::string::npos) {
            const int first = std::stoi(text.substr(0, dots)), last = std::stoi(text.substr(dots + 2));
            for (int k = first; k <= last; ++k) {
                keys.push_back(std::to_string(k));
            }
            continue;
        }
        std::stringstream parts(text);
        std::string part;
        while (std::getline(parts, part, ',')) {
            if (part.find("drag") != std::string::npos || part.find("wheel") != std::string::npos) {
                continue;
            }
            std::stringstream words(part);
            std::string word, prefix;
            while (words >> word) {
                if (word.rfind("Shift+", 0) == 0) {
                    prefix = "Shift+";
                    word = word.substr(6);
                }
                if (word != "Esc") {
                    keys.push_back(prefix + word);
                }
            }
        }
    }
    return keys;
}

} // namespace

TEST_SUITE("window") {

TEST_CASE("every key on every sample leaves the window running until Esc") {
    const std::string xvfb_run = window_test::find_on_path("xvfb-run");
    if (xvfb_run.empty()) {
        test_skips::skip("xvfb-run is not installed (scripts/install-deps.sh --window installs xvfb)");
        return;
    }
    const std::vector<std::string> keys = table_keys();
    REQUIRE(std::count(keys.begin(), keys.end(), "7") == 1); // the effect keys came through
    // Every key, then the effect keys again from the moved camera and mirror, then Esc.
    std::vector<std::string> sweep = keys;
    for (int k = 7; k >= 1; --k) {
        sweep.push_back(std::to_string(k));
    }
    std::string list;
    for (const std::string& key : sweep) {
        list += key + ",";
    }
    list += "Esc";
    const std::string frames = std::to_string(sweep.size() + 10); // Esc ends the run first

    struct Run {
        std::filesystem::path file;
        std::vector<std::string> extra;
    };
    std::vector<Run> runs;
    for (const auto& file : test_samples::scene_files()) {
        runs.push_back({file, {}});
        if (file.filename() == "Cameras.gltf") {
            runs.push_back({file, {"--camera", "1"}}); // orthographic
        }
    }
    for (const Run& run : runs) {
        std::vector<std::string> args{"-a", "-s", "-screen 0 640x480x24", kDemo, "window", "--scene",
                                      run.file.string(), "--size", "96x64", "--frames", frames, "--keys", list};
        args.insert(args.end(), run.extra.begin(), run.extra.end());
        const Child child = window_test::run(xvfb_run, args);
        INFO(run.file.filename().string() << (run.extra.empty() ? "" : " --camera 1") << ": " << child.err);
        CHECK(child.exit_status == 0);
        CHECK(child.err.find("error") == std::string::npos);
    }
}

} // TEST_SUITE
