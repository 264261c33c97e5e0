// Every key of the key table (window::key_help(), which docs/window.md
// lists) on every glTF sample and the showcase, under xvfb-run: the window
// keeps running through all of them (an effect that does not apply to the
// scene or camera keeps the previous one and says why) and ends with Esc,
// exit status 0. Also from an orthographic camera, where the effects
// built from an eye draw with its perspective twin. And on the
// showcase, each key changes exactly the setting its table entry names,
// read back from the state line the window writes after every frame
// (FRUSTUM_WINDOW_STATE, window::state_line()).
#include "process.hpp"

#include "../skips.hpp"

#include "../sample_files.hpp"

#include <doctest/doctest.h>

#include <window/key_help.hpp>

#include "support/temp_dir.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
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

// One line of FRUSTUM_WINDOW_STATE's log: "frame=N keys=K name=value ...".
struct StateLine {
    int keys = 0;
    std::map<std::string, std::string> fields; // without frame and keys
};

std::vector<StateLine> read_state_log(const std::filesystem::path& path) {
    std::vector<StateLine> lines;
    std::ifstream file(path);
    for (std::string text; std::getline(file, text);) {
        StateLine line;
        std::stringstream words(text);
        for (std::string word; words >> word;) {
            const std::size_t eq = word.find('=');
            REQUIRE_MESSAGE(eq != std::string::npos, text);
            const std::string name = word.substr(0, eq), value = word.substr(eq + 1);
            if (name == "keys") {
                line.keys = std::stoi(value);
            } else if (name != "frame") {
                line.fields[name] = value;
            }
        }
        lines.push_back(std::move(line));
    }
    return lines;
}

// The fields whose values differ between a and b.
std::set<std::string> changed(const std::map<std::string, std::string>& a, const std::map<std::string, std::string>& b) {
    std::set<std::string> names;
    for (const auto& [name, value] : a) {
        const auto other = b.find(name);
        if (other == b.end() || other->second != value) {
            names.insert(name);
        }
    }
    return names;
}

// The state_line() fields a key of the table names (its entry's action).
std::set<std::string> named_fields(const std::string& key) {
    const bool shift = key.rfind("Shift+", 0) == 0;
    const std::string k = shift ? key.substr(6) : key;
    if (k.size() == 1 && k[0] >= '1' && k[0] <= '9') return {"effect"};
    if (k == "A" || k == "D" || k == "W" || k == "S") return {shift ? "pan" : "orbit"};
    if (k == "Q" || k == "E") return {"zoom"};
    if (k == "R") return {"orbit", "pan", "zoom"};
    if (k == "Left" || k == "Right") return {shift ? "mirror.slide" : "mirror.turn"};
    if (k == "Up" || k == "Down") return {shift ? "mirror.push" : "mirror.tilt"};
    if (k == "M") return {"mirror.turn"}; // the sweep turns the mirror just before M
    if (k == "O") return {"mirror-camera"};
    if (k == "+" || k == "-") return {"tiles"};
    if (k == "[" || k == "]") return {"lens-power"};
    if (k == "," || k == ".") return {"depth"};
    if (k == "Z" || k == "X") return {shift ? "left.turn" : "left.push"};
    if (k == "C" || k == "V") return {shift ? "right.turn" : "right.push"};
    if (k == "F") return {"inset"};
    if (k == "P") return {"panel"};
    if (k == "H") return {"help"};
    return {};
}

} // namespace

TEST_SUITE("window") {

TEST_CASE("each key of the table changes exactly the setting it names, read back from the window's state") {
    const std::string xvfb_run = window_test::find_on_path("xvfb-run");
    if (xvfb_run.empty()) {
        test_skips::skip("xvfb-run is not installed (scripts/install-deps.sh --window installs xvfb)");
        return;
    }
    // K (bound to nothing) first: the state before any key. The window
    // starts on the mirror effect so that 1 (plain) changes it; the mirror
    // is turned (Left) again before M so that M has something to undo.
    std::vector<std::string> sweep{"K"};
    for (const std::string& key : table_keys()) {
        if (key == "M") {
            sweep.push_back("Left");
        }
        sweep.push_back(key);
    }
    std::string list;
    for (const std::string& key : sweep) {
        list += key + ",";
    }
    list += "Esc";
    support::TempDir dir;
    const std::filesystem::path state = dir / "state";
    const Child child = window_test::run(xvfb_run,
                                         {"-a", "-s", "-screen 0 640x480x24", kDemo, "window", "--size", "96x64",
                                          "--effect", "mirror", "--frames", std::to_string(sweep.size() + 10),
                                          "--keys", list},
                                         {{"FRUSTUM_WINDOW_STATE", state.string()}});
    REQUIRE_MESSAGE(child.exit_status == 0, child.err);
    const std::vector<StateLine> log = read_state_log(state.string() + ".log");
    REQUIRE(!log.empty());
    REQUIRE(log.front().keys == 1);
    // The state after k keys: the last logged line with at most k.
    const auto after = [&](std::size_t k) {
        const StateLine* found = nullptr;
        for (const StateLine& line : log) {
            if (static_cast<std::size_t>(line.keys) <= k) found = &line;
        }
        REQUIRE(found != nullptr);
        return found->fields;
    };
    const auto start = after(1);
    CHECK(start.at("effect") == "mirror");
    CHECK(start.at("orbit") == "scene");
    for (std::size_t i = 1; i < sweep.size(); ++i) {
        const std::string& key = sweep[i];
        const auto before = after(i), now = after(i + 1);
        std::set<std::string> expected = named_fields(key);
        REQUIRE_MESSAGE(!expected.empty(), key);
        // The first camera key starts the orbit where the scene's camera is: orbit, pan and zoom all appear.
        if (before.at("orbit") == "scene" && (expected.count("orbit") || expected.count("pan") || expected.count("zoom"))) {
            expected = {"orbit", "pan", "zoom"};
        }
        INFO("key " << key << " (#" << i << ")");
        const auto text = [](const std::set<std::string>& names) {
            std::string joined;
            for (const std::string& name : names) joined += name + " ";
            return joined;
        };
        CHECK(text(changed(before, now)) == text(expected));
        if (expected.count("effect")) {
            const int n = std::stoi(key);
            CHECK(now.at("effect") == std::string(plan::to_string(plan::kAllEffects[n - 1])));
        }
        if (key == "M") {
            for (const char* name : {"mirror.turn", "mirror.tilt", "mirror.slide", "mirror.push"}) {
                CHECK(now.at(name) == "0");
            }
        }
        if (key == "R") {
            CHECK(now.at("orbit") == "scene");
        }
    }
}

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
