// frustum-demo's one option table (app/demo/options.hpp), walked row by row:
// every command that declares an option accepts the row's example and
// answers every bad value the same way; the commands that do not declare it
// refuse it with one line naming it; --verbose and the budget options are
// accepted everywhere; each command's --help lists exactly its rows.
#include "process.hpp"

#include <doctest/doctest.h>

#include <demo/options.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

namespace {

const std::string kDemo = FRUSTUM_DEMO_EXE;

// What parse_options() answers, as text: "ok" or "error: <message>".
std::string outcome(demo::Command command, const std::vector<std::string>& options) {
    std::vector<std::string> args{demo::command_name(command)};
    args.insert(args.end(), options.begin(), options.end());
    const auto parsed = demo::parse_options(command, args);
    if (const auto* failure = std::get_if<demo::Failure>(&parsed)) {
        CHECK(failure->status == demo::ExitStatus::UsageError);
        CHECK(failure->message.find('\n') == std::string::npos);
        return "error: " + failure->message;
    }
    return std::holds_alternative<demo::Settings>(parsed) ? "ok" : "help";
}

std::vector<demo::Command> commands_of(const demo::Option& row) {
    std::vector<demo::Command> out;
    for (demo::Command command : demo::kCommands) {
        if (row.commands & command) {
            out.push_back(command);
        }
    }
    return out;
}

// parse_options()'s Settings; a failed REQUIRE when it answered anything else.
demo::Settings settings_of(demo::Command command, const std::vector<std::string>& options) {
    std::vector<std::string> args{demo::command_name(command)};
    args.insert(args.end(), options.begin(), options.end());
    auto parsed = demo::parse_options(command, args);
    REQUIRE(std::holds_alternative<demo::Settings>(parsed));
    return std::get<demo::Settings>(parsed);
}

const std::vector<std::string> kBadValues = {"", "0", "-1", "x!", "1e30", "3,", "0x0"};

// The help text of `name` in `command`'s --help, as frustum-demo prints it:
// the row's lines (after "  --name VALUE") trimmed and joined with spaces.
std::string help_of(demo::Command command, const std::string& name, const std::string& value) {
    const window_test::Child child = window_test::run(kDemo, {demo::command_name(command), "--help"});
    REQUIRE(child.exit_status == 0);
    const std::string head = "\n  " + name + " " + value + " ";
    const std::size_t at = child.out.find(head);
    REQUIRE_MESSAGE(at != std::string::npos, name << " not in the help of " << demo::command_name(command));
    const std::size_t end = std::min(child.out.find("\n  --", at + 1), child.out.find("\n\n", at + 1));
    std::istringstream lines(child.out.substr(at + head.size(), end - at - head.size()));
    std::string text;
    for (std::string line; std::getline(lines, line);) {
        line.erase(0, line.find_first_not_of(' '));
        text += (text.empty() ? "" : " ") + line;
    }
    return text;
}

// The parts joined with `separator` ("a | b | c"), to compare with a help text.
std::string joined(const std::vector<std::string>& parts, const std::string& separator) {
    std::string text;
    for (const std::string& part : parts) text += (text.empty() ? "" : separator) + part;
    return text;
}

// The text between `before` and the next `after`, in `text`.
std::string between(const std::string& text, const std::string& before, const std::string& after) {
    const std::size_t at = text.find(before);
    REQUIRE_MESSAGE(at != std::string::npos, "'" << before << "' not in: " << text);
    const std::size_t end = text.find(after, at + before.size());
    REQUIRE_MESSAGE(end != std::string::npos, "'" << after << "' not in: " << text);
    return text.substr(at + before.size(), end - at - before.size());
}

} // namespace

TEST_SUITE("window") {

TEST_CASE("demo option table: one row per name and command, each with help and an example") {
    std::set<std::pair<unsigned, std::string>> seen;
    for (const demo::Option& row : demo::options()) {
        CAPTURE(row.name);
        CHECK(row.name.rfind("--", 0) == 0);
        CHECK(!row.help.empty());
        CHECK(row.commands != 0u);
        CHECK((row.value == nullptr) == (row.example == nullptr));
        for (demo::Command command : commands_of(row)) {
            CHECK_MESSAGE(seen.insert({command, row.name}).second, "declared twice for ", demo::command_name(command));
        }
    }
}

TEST_CASE("demo option table: every command that declares an option accepts its example and answers bad values alike") {
    // Names with one value parser in several rows (one help line each);
    // --effect (a list in render, the first effect in window) and --patches
    // (one count in render and window, a list in curved-report) differ on purpose,
    // and --size (up to render::kMaxPosterSidePx in render, one target elsewhere).
    const std::set<std::string> differ = {"--effect", "--patches", "--size"};
    std::map<std::string, std::map<std::string, std::string>> by_name; // name -> bad value -> outcome
    for (const demo::Option& row : demo::options()) {
        for (demo::Command command : commands_of(row)) {
            CAPTURE(row.name);
            const std::string command_text = demo::command_name(command);
            CAPTURE(command_text);
            if (!row.value) {
                CHECK(outcome(command, {row.name}) == "ok");
                continue;
            }
            CHECK(outcome(command, {row.name, row.example}) == "ok");
            CHECK(outcome(command, {row.name}) == "error: " + row.name + " needs a value" + demo::help_hint(command));
            for (const std::string& bad : kBadValues) {
                CAPTURE(bad);
                const std::string got = outcome(command, {row.name, bad});
                const std::string key = differ.count(row.name) ? row.name + "/" + demo::command_name(command) : row.name;
                const auto [it, first] = by_name[key].emplace(bad, got);
                CHECK(it->second == got);
                if (got != "ok") {
                    CHECK(got.find("'" + bad + "'") != std::string::npos); // the message names the value
                }
            }
        }
    }
    CHECK(by_name.size() >= 30);
}

TEST_CASE("demo option table: a command refuses every option it does not declare, naming it") {
    for (const demo::Option& row : demo::options()) {
        for (demo::Command command : demo::kCommands) {
            if (demo::find_option(command, row.name)) {
                continue;
            }
            CAPTURE(row.name);
            const std::string command_text = demo::command_name(command);
            CAPTURE(command_text);
            std::vector<std::string> args{row.name};
            if (row.example) {
                args.push_back(row.example);
            }
            CHECK(outcome(command, args) == "error: " + row.name + " does not apply to " +
                                                demo::command_name(command) + demo::help_hint(command));
        }
    }
    // The options that reports used to forward to render and ignore.
    CHECK(outcome(demo::kLensReport, {"--patches", "8"}) ==
          "error: --patches does not apply to lens-report (see frustum-demo lens-report --help)");
    CHECK(outcome(demo::kNonAffineReport, {"--msaa", "4"}).find("does not apply to nonaffine-report") !=
          std::string::npos);
    CHECK(outcome(demo::kCurvedReport, {"--lens-power", "1.5"}).find("does not apply") != std::string::npos);
    CHECK(outcome(demo::kLensReport, {"--colour", "red"}) ==
          "error: unknown option '--colour' of lens-report (see frustum-demo lens-report --help)");
    CHECK(outcome(demo::kRender, {"--colour", "red"}) == "error: unknown option '--colour' (see frustum-demo --help)");
}

TEST_CASE("demo options: --verbose and the budget options mean the same in every command") {
    for (demo::Command command : demo::kCommands) {
        const std::string command_text = demo::command_name(command);
            CAPTURE(command_text);
        const auto parsed = demo::parse_options(
            command, {demo::command_name(command), "--verbose", "--max-memory-mb", "300", "--max-nodes", "7",
                      "--max-depth", "5", "--max-drawn-vertices", "1000"});
        REQUIRE(std::holds_alternative<demo::Settings>(parsed));
        const demo::Settings& s = std::get<demo::Settings>(parsed);
        CHECK(s.verbose);
        CHECK(s.budget.max_decoded_bytes == 300ull << 20);
        CHECK(s.budget.max_nodes == 7u);
        CHECK(s.budget.max_depth == 5u);
        CHECK(s.budget.max_drawn_vertices == 1000u);
    }
}

// Each option's value lands in its field, with the value written here by
// hand from the option's text (not from the parser), and a neighbouring
// default left as it was.
TEST_CASE("demo options: each option writes the value it was given") {
    const demo::Settings render_defaults = demo::defaults(demo::kRender);
    {
        const demo::Settings s = settings_of(demo::kRender, {"--scene", "city.gltf", "--camera", "2"});
        CHECK(s.scene_path == "city.gltf");
        REQUIRE(s.camera.has_value());
        CHECK(*s.camera == "2");
        CHECK(s.width_px == 640); // untouched: render's default 640x360
        CHECK(s.height_px == 360);
    }
    {
        const demo::Settings s = settings_of(demo::kRender, {"--size", "64x48"});
        CHECK(s.width_px == 64);
        CHECK(s.height_px == 48);
        CHECK(!s.poster);
        CHECK(!s.poster_tile_px.has_value());
        CHECK(s.out_dir == "out");
    }
    {
        const demo::Settings s = settings_of(demo::kRender, {"--size", "4096x2048", "--poster-tile", "32x16"});
        CHECK(s.width_px == 4096);
        CHECK(s.height_px == 2048);
        CHECK(s.poster);
        REQUIRE(s.poster_tile_px.has_value());
        CHECK(s.poster_tile_px->first == 32);
        CHECK(s.poster_tile_px->second == 16);
    }
    {
        const demo::Settings s = settings_of(demo::kRender, {"--size", "4096x2048", "--poster-tile", "auto"});
        CHECK(s.poster);
        CHECK(!s.poster_tile_px.has_value());
    }
    {
        const demo::Settings s = settings_of(demo::kRender, {"--depth", "minus_one_to_one", "--msaa", "2", "--out", "shots"});
        CHECK(s.depth == render::DepthPath::MinusOneToOne);
        CHECK(s.msaa_samples == 2);
        CHECK(s.out_dir == "shots");
        CHECK(s.width_px == render_defaults.width_px);
        CHECK(render_defaults.depth == render::DepthPath::ClipControlWhenAvailable);
        CHECK(render_defaults.msaa_samples == gl::kAutomaticSamples);
    }
    {
        const demo::Settings d = demo::defaults(demo::kWindow);
        CHECK(d.width_px == 960); // the window's default 960x540
        CHECK(d.height_px == 540);
        CHECK(d.context_api == gl::Api::Gles);
        CHECK(!d.inset);
        CHECK(!d.panel);
        CHECK(!d.help_overlay);
        CHECK(!d.frames.has_value());
        CHECK(!d.screenshot.has_value());
        CHECK(d.keys.empty());
        const demo::Settings s = settings_of(demo::kWindow, {"--context", "gl", "--inset", "--frames", "3",
                                                              "--screenshot", "shot.png", "--size", "64x48"});
        CHECK(s.context_api == gl::Api::GlCore);
        CHECK(s.inset);
        CHECK(!s.panel); // untouched
        CHECK(!s.help_overlay);
        REQUIRE(s.frames.has_value());
        CHECK(*s.frames == 3);
        REQUIRE(s.screenshot.has_value());
        CHECK(*s.screenshot == "shot.png");
        CHECK(s.width_px == 64);
        CHECK(s.height_px == 48);
        const demo::Settings p = settings_of(demo::kWindow, {"--panel", "--help-overlay", "--context", "es"});
        CHECK(p.panel);
        CHECK(p.help_overlay);
        CHECK(!p.inset);
        CHECK(p.context_api == gl::Api::Gles);
        CHECK(settings_of(demo::kWindow, {"--keys", "1,Shift+Left,h"}).keys.size() == 3u);
    }
    {
        const demo::Settings s = settings_of(demo::kCurvedReport, {"--patches", "1,4"});
        CHECK(s.patch_counts == std::vector<int>{1, 4});
        CHECK(s.width_px == 640); // reports: 640x360
        CHECK(s.height_px == 360);
    }
    {
        const demo::Settings d = demo::defaults(demo::kLensReport);
        CHECK(d.grids == std::vector<int>{4, 8, 16, 32});
        CHECK(d.supersampling == 4);
        CHECK(d.runs == 5);
        const demo::Settings s = settings_of(demo::kLensReport, {"--grids", "4,8", "--supersampling", "2"});
        CHECK(s.grids == std::vector<int>{4, 8});
        CHECK(s.supersampling == 2);
        CHECK(s.runs == 5); // untouched
        CHECK(settings_of(demo::kLensReport, {"--runs", "3"}).runs == 3);
    }
    {
        const demo::Settings d = demo::defaults(demo::kNonAffineReport);
        CHECK(d.max_edges_m == std::vector<float>{0.0f, 1.0f, 0.5f, 0.25f, 0.1f});
        const demo::Settings s = settings_of(demo::kNonAffineReport, {"--edges", "0,0.5", "--runs", "7"});
        CHECK(s.max_edges_m == std::vector<float>{0.0f, 0.5f}); // metres, 0 and 0.5 exact in float
        CHECK(s.runs == 7);
    }
}

// The effect rows (demo/effect_options.hpp) write plan::EffectParams; the
// values are the option text's, metres where the name says so, written
// here by hand; exact float equality: each is parsed from the same decimal.
TEST_CASE("demo options: each effect option writes the value it was given") {
    for (demo::Command command : {demo::kRender, demo::kWindow}) {
        const std::string command_text = demo::command_name(command);
        CAPTURE(command_text);
        const demo::Settings d = demo::defaults(command);
        CHECK(d.tile_columns == 3); // default 3x2
        CHECK(d.tile_rows == 2);
        CHECK(!d.tile_borders);
        CHECK(d.mirror_method == plan::MirrorMethod::Oblique);
        CHECK(d.curved.patches == 4);
        CHECK(d.curved.shape == plan::CapShape::Sphere);
        CHECK(!d.sagitta_given);
        CHECK(d.lens_grid == 16);
        CHECK(d.lens_power == 2.0f);
        CHECK(!d.fog.has_value());
        CHECK(!d.stereo);
        CHECK(d.ipd_m == 0.064f);
        CHECK(!d.convergence_m.has_value());
        CHECK(d.recursion_depth == 4);
        CHECK(d.recursion_links == plan::LinkSet::Mirrors);
        CHECK(!d.mirror_place.plane.has_value());
        CHECK(!d.mirror_place.rect.has_value());

        const demo::Settings t = settings_of(command, {"--tiles", "4x3", "--tile-borders", "--mirror", "rectangle"});
        CHECK(t.tile_columns == 4);
        CHECK(t.tile_rows == 3);
        CHECK(t.tile_borders);
        CHECK(t.mirror_method == plan::MirrorMethod::Rectangle);
        CHECK(t.lens_grid == 16); // untouched
        CHECK(settings_of(command, {"--mirror", "reflect_only"}).mirror_method == plan::MirrorMethod::ReflectOnly);

        const demo::Settings plane = settings_of(command, {"--mirror-plane", "0,1,0,-0.5"});
        REQUIRE(plane.mirror_place.plane.has_value());
        CHECK(plane.mirror_place.plane->x == 0.0f);
        CHECK(plane.mirror_place.plane->y == 1.0f);
        CHECK(plane.mirror_place.plane->z == 0.0f);
        CHECK(plane.mirror_place.plane->w == -0.5f);
        CHECK(!plane.mirror_place.rect.has_value());

        const demo::Settings rect = settings_of(command, {"--mirror-rect", "1,2,3,4,5,6,7,8,9"});
        REQUIRE(rect.mirror_place.rect.has_value());
        CHECK(*rect.mirror_place.rect == std::array<float, 9>{1, 2, 3, 4, 5, 6, 7, 8, 9});

        const demo::Settings curved = settings_of(command, {"--patches", "8", "--sagitta", "0.1", "--cap", "cylinder"});
        CHECK(curved.curved.patches == 8);
        CHECK(curved.curved.sagitta_m == 0.1f);
        CHECK(curved.sagitta_given);
        CHECK(curved.curved.shape == plan::CapShape::Cylinder);

        const demo::Settings lens = settings_of(command, {"--lens-grid", "8", "--lens-power", "1.5",
                                                          "--lens-center", "0.1,-0.2", "--lens-radius", "0.3"});
        CHECK(lens.lens_grid == 8);
        CHECK(lens.lens_power == 1.5f);
        REQUIRE(lens.fit.lens_center.has_value());
        CHECK(lens.fit.lens_center->x == 0.1f);
        CHECK(lens.fit.lens_center->y == -0.2f);
        REQUIRE(lens.fit.lens_radius.has_value());
        CHECK(*lens.fit.lens_radius == 0.3f);
        CHECK(!lens.fit.slit_m.has_value()); // untouched

        const demo::Settings nonaffine = settings_of(command, {"--slit", "2", "--pivot", "5"});
        REQUIRE(nonaffine.fit.slit_m.has_value());
        CHECK(*nonaffine.fit.slit_m == 2.0f);
        REQUIRE(nonaffine.fit.pivot_m.has_value());
        CHECK(*nonaffine.fit.pivot_m == 5.0f);
        CHECK(!nonaffine.fit.lens_center.has_value());

        const demo::Settings fog = settings_of(command, {"--fog"});
        REQUIRE(fog.fog.has_value());
        CHECK(!fog.fog->color.has_value()); // the sky
        CHECK(!fog.fog->density_per_m.has_value());
        const demo::Settings fog_set = settings_of(command, {"--fog-density", "0.05", "--fog-color", "0.5,0.6,0.7"});
        REQUIRE(fog_set.fog.has_value()); // implies --fog
        REQUIRE(fog_set.fog->density_per_m.has_value());
        CHECK(*fog_set.fog->density_per_m == 0.05f);
        REQUIRE(fog_set.fog->color.has_value());
        CHECK(fog_set.fog->color->r == 0.5f);
        CHECK(fog_set.fog->color->g == 0.6f);
        CHECK(fog_set.fog->color->b == 0.7f);

        const demo::Settings stereo = settings_of(command, {"--stereo", "--ipd-m", "0.1", "--convergence-m", "4"});
        CHECK(stereo.stereo);
        CHECK(stereo.ipd_m == 0.1f);
        REQUIRE(stereo.convergence_m.has_value());
        CHECK(*stereo.convergence_m == 4.0f);

        const demo::Settings recursion = settings_of(command, {"--recursion-depth", "2", "--recursion-links", "portals"});
        CHECK(recursion.recursion_depth == 2);
        CHECK(recursion.recursion_links == plan::LinkSet::Portals);
        CHECK(settings_of(command, {"--recursion-depth", "0"}).recursion_depth == 0);
    }
    // The reports' share of the effect rows.
    const demo::Settings c = settings_of(demo::kCurvedReport, {"--sagitta", "0.25", "--cap", "cylinder"});
    CHECK(c.curved.sagitta_m == 0.25f);
    CHECK(c.curved.shape == plan::CapShape::Cylinder);
    CHECK(settings_of(demo::kLensReport, {"--lens-power", "1.5"}).lens_power == 1.5f);
    const demo::Settings n = settings_of(demo::kNonAffineReport, {"--slit", "2.6", "--pivot", "8"});
    REQUIRE(n.fit.slit_m.has_value());
    CHECK(*n.fit.slit_m == 2.6f);
    REQUIRE(n.fit.pivot_m.has_value());
    CHECK(*n.fit.pivot_m == 8.0f);
}

// The renderer draws up to kMaxTiles tiles (128 x 128), at most one per
// pixel; the window's + and - keys step within 1..16 per direction, which
// is no reason to refuse a larger start: both commands take the same bound.
TEST_CASE("demo options: --tiles has the same bound in render and window") {
    for (demo::Command command : {demo::kRender, demo::kWindow}) {
        const std::string command_text = demo::command_name(command);
            CAPTURE(command_text);
        const auto parsed = demo::parse_options(command, {demo::command_name(command), "--tiles", "20x2"});
        REQUIRE(std::holds_alternative<demo::Settings>(parsed));
        CHECK(std::get<demo::Settings>(parsed).tile_columns == 20);
        CHECK(std::get<demo::Settings>(parsed).tile_rows == 2);
        CHECK(outcome(command, {"--tiles", "128x128"}) == "ok");
        CHECK(outcome(command, {"--tiles", "129x128"}) ==
              "error: --tiles 129x128 is 16512 tiles, over the limit of 16384");
        CHECK(outcome(command, {"--tiles", "8193x1"}).find("--tiles must be NxM") != std::string::npos);
    }
}

// The value lists, written here by hand: each accepted value parses to its
// enum value, a near miss is refused, and the help lists exactly these.
TEST_CASE("demo options: --effect accepts exactly the effects its help lists, each parsed to its effect") {
    using Effect = plan::Effect;
    const std::vector<std::pair<std::string, Effect>> effects = {
        {"plain", Effect::Plain},   {"mirror", Effect::Mirror},       {"tiles", Effect::Tiles},
        {"frustum", Effect::Frustum}, {"curved", Effect::Curved},     {"lens", Effect::Lens},
        {"nonaffine", Effect::NonAffine}, {"portal", Effect::Portal}, {"recursion", Effect::Recursion}};
    std::vector<std::string> names;
    std::vector<Effect> all;
    for (const auto& [name, effect] : effects) {
        const auto& value = name; // CAPTURE cannot take a structured binding (clang, C++17)
        CAPTURE(value);
        names.push_back(name);
        all.push_back(effect);
        CHECK(settings_of(demo::kRender, {"--effect", name}).effects == std::vector<Effect>{effect});
        CHECK(settings_of(demo::kWindow, {"--effect", name}).effects == std::vector<Effect>{effect});
        std::string upper = name;
        for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
        CHECK(outcome(demo::kRender, {"--effect", upper}).rfind("error: unknown effect '" + upper + "'", 0) == 0);
    }
    CHECK(std::vector<Effect>(std::begin(plan::kAllEffects), std::end(plan::kAllEffects)) == all);
    CHECK(settings_of(demo::kRender, {"--effect", "all"}).effects == all);
    CHECK(demo::defaults(demo::kRender).effects == all);
    CHECK(demo::defaults(demo::kWindow).effects == std::vector<Effect>{Effect::Plain});
    CHECK(outcome(demo::kWindow, {"--effect", "all"}).rfind("error: unknown effect 'all'", 0) == 0);
    CHECK(outcome(demo::kRender, {"--effect", "plain,mirror"}).rfind("error: unknown effect", 0) == 0);
    // render: "plain | mirror | ... | all (default all)"; window: "first effect: plain, mirror, ... (default plain)".
    std::vector<std::string> with_all = names;
    with_all.push_back("all");
    CHECK(between(" " + help_of(demo::kRender, "--effect", "E"), " ", " (default all)") == joined(with_all, " | "));
    CHECK(between(help_of(demo::kWindow, "--effect", "E"), "first effect: ", " (default plain)") ==
          joined(names, ", "));
    // The refusal names the same list.
    CHECK(outcome(demo::kRender, {"--effect", "x"}) ==
          "error: unknown effect 'x' (expected plain, mirror, tiles, frustum, curved, lens, nonaffine, portal, "
          "recursion or all)");
}

TEST_CASE("demo options: --backend accepts exactly egl and osmesa, as its help lists") {
    const std::vector<std::pair<std::string, gl::Backend>> backends = {{"egl", gl::Backend::Egl},
                                                                       {"osmesa", gl::Backend::OsMesa}};
    std::vector<std::string> names;
    for (demo::Command command : {demo::kRender, demo::kLensReport, demo::kCurvedReport, demo::kNonAffineReport}) {
        const std::string command_text = demo::command_name(command);
        CAPTURE(command_text);
        CHECK(!demo::defaults(command).backend.has_value()); // unset: EGL, else OSMesa with a note
        for (const auto& [name, backend] : backends) {
            const auto& value = name; // CAPTURE cannot take a structured binding (clang, C++17)
            CAPTURE(value);
            const demo::Settings s = settings_of(command, {"--backend", name});
            REQUIRE(s.backend.has_value());
            CHECK(*s.backend == backend);
        }
        for (const std::string near_miss : {"webgl", "EGL", "OSMesa", "gles", "egl,osmesa"}) {
            CHECK(outcome(command, {"--backend", near_miss}) ==
                  "error: unknown backend '" + near_miss + "' (expected egl or osmesa)");
        }
        CHECK(between(" " + help_of(command, "--backend", "B"), " ", " (default") == "egl | osmesa");
    }
}

TEST_CASE("demo options: --keys parses every key its help names, any printable character, Shift+, in order") {
    using gl::Key;
    const auto keys = [](const std::string& list) { return settings_of(demo::kWindow, {"--keys", list}).keys; };
    // The named keys, by hand.
    const std::vector<std::pair<std::string, Key>> named = {
        {"Left", Key::Left}, {"Right", Key::Right}, {"Up", Key::Up}, {"Down", Key::Down}, {"Esc", Key::Escape}};
    std::vector<std::string> names;
    for (const auto& [name, key] : named) {
        const auto& value = name; // CAPTURE cannot take a structured binding (clang, C++17)
        CAPTURE(value);
        names.push_back(name);
        for (const bool shift : {false, true}) {
            const auto parsed = keys(shift ? "Shift+" + name : name);
            REQUIRE(parsed.size() == 1u);
            CHECK(parsed[0].key == key);
            CHECK(parsed[0].character == 0);
            CHECK(parsed[0].mods.shift == shift);
            CHECK(!parsed[0].mods.control);
            CHECK(!parsed[0].mods.alt);
        }
    }
    // Every printable ASCII character but the space, letters as their upper case.
    for (int c = 33; c < 127; ++c) {
        const std::string item(1, char(c));
        CAPTURE(item);
        const char expected = (c >= 'a' && c <= 'z') ? char(c - 'a' + 'A') : char(c);
        for (const bool shift : {false, true}) {
            const auto parsed = keys(shift ? "Shift+" + item : item);
            REQUIRE(parsed.size() == 1u);
            CHECK(parsed[0].key == Key::Character);
            CHECK(parsed[0].character == expected);
            CHECK(parsed[0].mods.shift == shift);
        }
    }
    // A list, one press per item, in order; the comma key last.
    const auto list = keys("1,Shift+Left,+,h,Esc,Shift+,,,");
    REQUIRE(list.size() == 7u);
    CHECK((list[0].key == Key::Character && list[0].character == '1' && !list[0].mods.shift));
    CHECK((list[1].key == Key::Left && list[1].mods.shift));
    CHECK((list[2].key == Key::Character && list[2].character == '+'));
    CHECK((list[3].key == Key::Character && list[3].character == 'H' && !list[3].mods.shift));
    CHECK(list[4].key == Key::Escape);
    CHECK((list[5].key == Key::Character && list[5].character == ',' && list[5].mods.shift));
    CHECK((list[6].key == Key::Character && list[6].character == ',' && !list[6].mods.shift));
    // Not keys: what the help does not name.
    for (const std::string bad : {"", "left", "Enter", "PageUp", "Home", "Space", " ", "Shift+", "Shift+Shift+A",
                                  "Ctrl+A", "ab", "\x7f", "\xc3\xa9", "1,,2", "Shift+,1"}) {
        CAPTURE(bad);
        CHECK(outcome(demo::kWindow, {"--keys", bad}).rfind("error: --keys must be a comma-separated list", 0) == 0);
    }
    // The help: "(a character, Left, Right, Up, Down, Esc)"; the refusal names them and Shift+KEY.
    CHECK(between(help_of(demo::kWindow, "--keys", "LIST"), "(a character, ", ")") == joined(names, ", "));
    CHECK(outcome(demo::kWindow, {"--keys", "Tab"}) ==
          "error: --keys must be a comma-separated list of keys (a character, Left, Right, Up, Down, Esc, "
          "Shift+KEY), got 'Tab'");
}

TEST_CASE("demo options: each command's --help lists exactly its rows of the table") {
    for (demo::Command command : demo::kCommands) {
        const std::string command_text = demo::command_name(command);
            CAPTURE(command_text);
        const window_test::Child child = window_test::run(kDemo, {demo::command_name(command), "--help"});
        REQUIRE(child.exit_status == 0);
        std::multiset<std::string> listed, declared;
        for (std::size_t at = child.out.find("\n  --"); at != std::string::npos; at = child.out.find("\n  --", at + 1)) {
            const std::size_t end = child.out.find_first_of(" \n", at + 3);
            listed.insert(child.out.substr(at + 3, end - at - 3));
        }
        for (const demo::Option& row : demo::options()) {
            if (row.commands & command) {
                declared.insert(row.name);
            }
        }
        CHECK(listed == declared);
    }
}

} // TEST_SUITE
