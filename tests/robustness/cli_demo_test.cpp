// frustum-demo render as a built binary: usage errors exit 2 before any
// work (the output folder is not even created), runtime failures exit 1
// with the reason; stdout (the paths written) stays empty and no file is
// left behind: no PNG, no "*.tmp*" from an interrupted write, no probe.
#ifdef FRUSTUM_DEMO_EXE
#include "support.hpp"

#include "../skips.hpp"

#include <doctest/doctest.h>


#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <signal.h>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;

enum class Out { NotCreated, NoFiles };

struct DemoCase {
    const char* input;
    std::function<std::vector<std::string>(const support::TempDir&)> args; // may create files in the folder
    int exit_status;
    std::vector<std::string> phrases; // on stderr
    Out out;
};

// "render" + the given options, with --out <tmp>/out appended.
std::function<std::vector<std::string>(const support::TempDir&)> render(std::vector<std::string> options) {
    return [options](const support::TempDir& dir) {
        std::vector<std::string> args{"render"};
        args.insert(args.end(), options.begin(), options.end());
        args.insert(args.end(), {"--out", (dir / "out").string()});
        return args;
    };
}

// A scene file in the temp folder with the given text.
std::function<std::vector<std::string>(const support::TempDir&)> scene_text(std::string text) {
    return [text](const support::TempDir& dir) {
        support::write_file(dir / "scene.gltf", text);
        return render({"--scene", (dir / "scene.gltf").string()})(dir);
    };
}

const std::string kTriangle = std::string(FRUSTUM_SOURCE_DIR) + "/tests/data/gltf-models/triangle.gltf";

const std::vector<DemoCase>& demo_cases() {
    static const std::vector<DemoCase> cases = {
        {"no command", [](const support::TempDir&) { return std::vector<std::string>{}; }, 2,
         {"frustum-demo: error: expected a command: render"}, Out::NotCreated},
        {"unknown command", [](const support::TempDir& d) { return std::vector<std::string>{"draw", "--out", (d / "out").string()}; },
         2, {"unknown command 'draw'"}, Out::NotCreated},
        {"unknown option", render({"--colour", "red"}), 2, {"unknown option '--colour'"}, Out::NotCreated},
        {"--size 0x10", render({"--size", "0x10"}), 2, {"--size must be WxH with 1..65536 each, got '0x10'"}, Out::NotCreated},
        {"--size 65537x1", render({"--size", "65537x1"}), 2, {"--size must be WxH", "'65537x1'"}, Out::NotCreated},
        {"--size -5x5", render({"--size", "-5x5"}), 2, {"--size must be WxH", "'-5x5'"}, Out::NotCreated},
        {"--tiles 0x2", render({"--tiles", "0x2"}), 2, {"--tiles must be NxM", "'0x2'"}, Out::NotCreated},
        {"more tiles than pixels", render({"--size", "64x36", "--tiles", "65x1"}), 2,
         {"--tiles 65x1 needs at least one pixel per tile"}, Out::NotCreated},
        {"unknown effect", render({"--effect", "sparkle"}), 2, {"unknown effect 'sparkle'"}, Out::NotCreated},
        {"unknown backend", render({"--backend", "vulkan"}), 2, {"unknown backend 'vulkan'"}, Out::NotCreated},
        {"unknown depth range", render({"--depth", "reversed"}), 2, {"unknown depth range 'reversed'"}, Out::NotCreated},
        {"unknown mirror method", render({"--mirror", "curved"}), 2, {"unknown mirror method 'curved'"}, Out::NotCreated},
        {"--msaa 0", render({"--msaa", "0"}), 2, {"--msaa must be a sample count in 1..64 (1 = off), got '0'"},
         Out::NotCreated},
        {"--msaa 65", render({"--msaa", "65"}), 2, {"--msaa must be a sample count in 1..64 (1 = off), got '65'"},
         Out::NotCreated},
        {"--msaa beyond the context", render({"--effect", "plain", "--msaa", "64"}), 1,
         {"frustum-demo: error: --msaa 64: gl::choose_samples(): 64 samples requested, but this context offers 1 to "},
         Out::NoFiles},
        {"--slit 0", render({"--slit", "0"}), 2, {"--slit must be a depth in (0, 1000] metres, got '0'"}, Out::NotCreated},
        {"--lens-radius 2", render({"--lens-radius", "2"}), 2,
         {"--lens-radius must be a fraction of the frame's half height in (0, 1], got '2'"}, Out::NotCreated},
        {"--lens-center 0", render({"--lens-center", "0"}), 2, {"--lens-center must be x,y", "got '0'"}, Out::NotCreated},
        {"--fog-density 0", render({"--fog-density", "0"}), 2,
         {"--fog-density must be a number in (0, 1000] per metre, got '0'"}, Out::NotCreated},
        {"--fog-color 1,2,0", render({"--fog-color", "1,2,0"}), 2,
         {"--fog-color must be r,g,b with each in [0, 1] (sRGB-encoded), got '1,2,0'"}, Out::NotCreated},
        {"--mirror-rect with parallel sides", render({"--mirror-rect", "0,0,0,1,0,0,2,0,0"}), 2,
         {"--mirror-rect must be cx,cy,cz,ax,ay,az,bx,by,bz", "'0,0,0,1,0,0,2,0,0'"}, Out::NotCreated},
        {"--mirror-plane with 3 numbers", render({"--mirror-plane", "0,1,0"}), 2, {"--mirror-plane must be a,b,c,d"},
         Out::NotCreated},
        {"both mirror placements", render({"--mirror-plane", "0,1,0,0", "--mirror-rect", "0,0,0,1,0,0,0,1,0"}), 2,
         {"--mirror-plane and --mirror-rect both place the mirror"}, Out::NotCreated},
        {"--pivot beyond the far plane", render({"--effect", "nonaffine", "--pivot", "900", "--size", "64x36"}), 1,
         {"nonaffine: --pivot 900 must be less than the far distance"}, Out::NoFiles},
        {"--stereo with an odd width", render({"--stereo", "--size", "65x36"}), 2,
         {"--stereo needs an even width (two eyes side by side), got --size 65x36"}, Out::NotCreated},
        {"--ipd-m -1", render({"--ipd-m", "-1"}), 2, {"--ipd-m must be a distance in [0, 10] metres, got '-1'"},
         Out::NotCreated},
        {"--convergence-m before the near plane", render({"--stereo", "--convergence-m", "0.01", "--size", "64x36"}), 1,
         {"frustum-demo: error: plan::stereo_eyes(): convergence 0.01 m must be beyond the near plane"},
         Out::NoFiles},
        {"--sagitta too large for the mirror", render({"--effect", "curved", "--sagitta", "50", "--size", "64x36"}), 2,
         {"--sagitta 50 must be in [0, "}, Out::NotCreated},
        {"empty --out", [](const support::TempDir&) { return std::vector<std::string>{"render", "--out", ""}; }, 2,
         {"--out needs a folder"}, Out::NotCreated},
        {"--scene without a value", [](const support::TempDir& d) {
             return std::vector<std::string>{"render", "--out", (d / "out").string(), "--scene"};
         }, 2, {"--scene needs a value"}, Out::NotCreated},
        {"unknown camera", render({"--scene", kTriangle, "--camera", "nosuch"}), 2, {"no camera 'nosuch'"}, Out::NoFiles},
        {"missing scene", [](const support::TempDir& d) { return render({"--scene", (d / "none.gltf").string()})(d); }, 1,
         {"frustum-demo: error: scene::load_gltf(): ", "none.gltf\" does not exist"}, Out::NoFiles},
        {"scene that is not glTF", scene_text("GIF89a"), 1, {"not a glTF file"}, Out::NoFiles},
        {"scene with uri \"..\"", scene_text(R"({"asset": {"version": "2.0"}, "buffers": [{"uri": "../x.bin", "byteLength": 4}]})"),
         1, {"buffer 0 uri \"../x.bin\"", "outside the model folder"}, Out::NoFiles},
        {"--out below a regular file", [](const support::TempDir& d) {
             support::write_file(d / "file", "x");
             return std::vector<std::string>{"render", "--out", (d / "file" / "out").string()};
         }, 1, {"cannot create output folder", "Not a directory"}, Out::NotCreated},
        {"--out read-only", [](const support::TempDir& d) {
             // root ignores permission bits: /sys refuses new files even to root.
             std::string ro = "/sys";
             if (::geteuid() != 0) {
                 fs::create_directory(d / "ro");
                 fs::permissions(d / "ro", fs::perms::owner_read | fs::perms::owner_exec);
                 ro = (d / "ro").string();
             }
             return std::vector<std::string>{"render", "--effect", "plain", "--out", ro};
         }, 1, {"cannot write to output folder", "Permission denied"}, Out::NotCreated},
    };
    return cases;
}

// Files below `dir` whose name contains ".tmp" or ends in ".png".
std::vector<std::string> leftovers(const fs::path& dir) {
    std::vector<std::string> found;
    std::error_code error;
    for (const auto& entry : fs::recursive_directory_iterator(dir, error)) {
        const std::string name = entry.path().filename().string();
        if (name.find(".tmp") != std::string::npos || name.find(".png") != std::string::npos ||
            name.find("probe") != std::string::npos) {
            found.push_back(entry.path().string());
        }
    }
    return found;
}

std::string joined(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
    return text;
}

} // namespace

TEST_SUITE("robustness") {

TEST_CASE("frustum-demo: usage errors exit 2, runtime failures exit 1, nothing written") {
    support::for_each_case(demo_cases(), 18, [](const DemoCase& c) {
        support::TempDir dir;
        support::Launch launch;
        launch.args = c.args(dir);
        launch.cwd = dir.path().string(); // the default --out "out" would land here
        const support::Outcome r = rob::run_checked(FRUSTUM_DEMO_EXE, launch, c.exit_status, true);
        CAPTURE(r.err);
        CHECK(r.err.rfind("frustum-demo: error: ", 0) == 0);
        support::check_phrases(r.err, c.phrases);
        if (c.out == Out::NotCreated) {
            CHECK_FALSE(fs::exists(dir / "out"));
        } else {
            CHECK(rob::list_dir(dir / "out").empty());
        }
        CHECK_MESSAGE(leftovers(dir.path()).empty(), "left behind: ", joined(leftovers(dir.path())));
    });
}

TEST_CASE("frustum-demo: an effect of several that fails leaves the others and the sheet, exit 1 naming it") {
    support::TempDir dir;
    support::Launch launch;
    launch.args = {"render", "--pivot", "900", "--size", "64x36", "--out", (dir / "out").string()};
    if (rob::no_gl()) return;
    const support::Outcome r = support::run(FRUSTUM_DEMO_EXE, launch);
    CAPTURE(r.err);
    CHECK(r.exit_status == 1);
    CHECK(r.err.find("frustum-demo: error: effect nonaffine: --pivot 900 must be less than the far distance") !=
          std::string::npos);
    for (const char* name : {"plain", "mirror", "tiles", "frustum", "curved", "lens", "contact_sheet"}) {
        CAPTURE(name);
        const std::string path = (dir / "out" / (std::string(name) + ".png")).string();
        CHECK(fs::exists(path));
        CHECK(r.out.find(path + "\n") != std::string::npos);
    }
    CHECK_FALSE(fs::exists(dir / "out" / "nonaffine.png"));
}

TEST_CASE("frustum-demo: a write that fails midway (file size limit) leaves no PNG and no temp file") {
    support::TempDir dir;
    support::Launch launch;
    launch.args = {"render", "--effect", "plain", "--size", "640x360", "--out", (dir / "out").string()};
    launch.file_size_limit_bytes = 4096; // the PNG is larger: write() fails with EFBIG
    if (rob::no_gl()) return;
    const support::Outcome r = support::run(FRUSTUM_DEMO_EXE, launch);
    CAPTURE(r.err);
    CHECK(r.signal == 0);
    CHECK(r.exit_status == 1);
    CHECK(r.out.empty());
    CHECK(r.err.find("frustum-demo: error: image::write_png(): cannot write '") == 0);
    CHECK(r.err.find("File too large") != std::string::npos);
    CHECK_MESSAGE(leftovers(dir.path()).empty(), "left behind: ", joined(leftovers(dir.path())));
}

TEST_CASE("frustum-demo: killed in the middle of a write, no partial PNG under the final name") {
    support::TempDir dir;
    support::Launch launch;
    launch.args = {"render", "--effect", "plain", "--size", "640x360", "--out", (dir / "out").string()};
    launch.file_size_limit_bytes = 4096;
    launch.ignore_sigxfsz = false; // SIGXFSZ kills the process inside write()
    if (rob::no_gl()) return;
    const support::Outcome r = support::run(FRUSTUM_DEMO_EXE, launch);
    CAPTURE(r.err);
    CHECK(r.signal == SIGXFSZ);
    CHECK_FALSE(fs::exists(dir / "out" / "plain.png"));
    // What a killed process leaves: at most its own temp file, never a PNG.
    for (const std::string& name : rob::list_dir(dir / "out")) {
        CAPTURE(name);
        CHECK(name.rfind("plain.png.tmp-", 0) == 0);
    }
}

} // TEST_SUITE
#endif
