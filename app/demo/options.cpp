#include "demo/options.hpp"

#include "demo/option_values.hpp"

#include <render/poster.hpp>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <iterator>
#include <string_view>
#include <tuple>
#include <utility>

namespace demo {
namespace {

constexpr int kMaxSidePx = 8192;
constexpr int kMaxFrames = 1000000;
constexpr unsigned kOffscreen = kRender | kReports; // --backend, --out; --depth (and window)

using Apply = std::optional<Failure> (*)(Settings&, const std::string&);

std::string quoted(const std::string& value) { return "'" + value + "'"; }

// "a,b,c" -> values, each accepted by `accept`.
template <class T, class Accept>
std::optional<std::vector<T>> parse_list(const std::string& text, Accept accept) {
    std::vector<T> out;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        const char* first = text.data() + start;
        const char* last = text.data() + comma;
        T value{};
        const auto [end, error] = std::from_chars(first, last, value);
        if (first == last || error != std::errc() || end != last || !accept(value)) {
            return std::nullopt;
        }
        out.push_back(value);
        start = comma + 1;
    }
    return out;
}

// "1,Shift+Left,+,h": one key press per item (letters in either case).
std::optional<std::vector<gl::KeyPressed>> parse_keys(std::string_view text) {
    std::vector<gl::KeyPressed> keys;
    while (!text.empty()) {
        // Items are split at the first comma after their first key character
        // (after "Shift+" if they start with it), so "," and "Shift+," are the
        // comma key.
        const std::size_t key_start = text.substr(0, 6) == "Shift+" ? 6 : 0;
        const std::size_t comma = text.find(',', key_start + 1);
        std::string_view item = text.substr(0, comma);
        text = comma == std::string_view::npos ? std::string_view() : text.substr(comma + 1);
        gl::KeyPressed key;
        if (item.size() > 6 && item.substr(0, 6) == "Shift+") {
            key.mods.shift = true;
            item.remove_prefix(6);
        }
        if (item == "Left" || item == "Right" || item == "Up" || item == "Down" || item == "Esc") {
            key.key = item == "Left" ? gl::Key::Left : item == "Right" ? gl::Key::Right : item == "Up" ? gl::Key::Up
                      : item == "Down" ? gl::Key::Down : gl::Key::Escape;
        } else if (item.size() == 1 && item[0] > ' ' && item[0] < 127) {
            key.key = gl::Key::Character;
            key.character = static_cast<char>(std::toupper(static_cast<unsigned char>(item[0])));
        } else {
            return std::nullopt;
        }
        keys.push_back(key);
    }
    if (keys.empty()) {
        return std::nullopt;
    }
    return keys;
}

// --size of the window and the reports (one GPU target) and of render (a
// poster above one target: render::kMaxPosterSidePx).
template <int most>
std::optional<Failure> apply_size(Settings& s, const std::string& value) {
    const auto size = parse_pair(value, most);
    if (!size) {
        return usage("--size must be WxH with 1.." + std::to_string(most) + " each, got " + quoted(value));
    }
    std::tie(s.width_px, s.height_px) = *size;
    return std::nullopt;
}

std::optional<Failure> apply_poster_tile(Settings& s, const std::string& value) {
    if (value == "auto") {
        s.poster = true;
        s.poster_tile_px.reset();
        return std::nullopt;
    }
    const auto size = parse_pair(value, kMaxSidePx);
    if (!size) {
        return usage("--poster-tile must be WxH with 1.." + std::to_string(kMaxSidePx) + " each, or auto, got " +
                     quoted(value));
    }
    s.poster = true;
    s.poster_tile_px = *size;
    return std::nullopt;
}

// --max-memory-mb, --max-nodes, --max-depth, --max-drawn-vertices: whole
// numbers in 1..2^40 MiB and 1..2^60 counts (far above any machine, below
// uint64 overflow).
template <const char* name>
std::optional<Failure> apply_budget(Settings& s, const std::string& value) {
    const std::string_view option = name;
    unsigned long long number = 0;
    const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), number);
    const unsigned long long most = option == "--max-memory-mb" ? (1ull << 40) : (1ull << 60);
    if (value.empty() || error != std::errc() || end != value.data() + value.size() || number < 1 ||
        number > most) {
        return usage(std::string(option) + " must be a whole number in 1.." + std::to_string(most) + ", got " +
                     quoted(value));
    }
    if (option == "--max-memory-mb") {
        s.budget.max_decoded_bytes = number << 20;
    } else if (option == "--max-nodes") {
        s.budget.max_nodes = number;
    } else if (option == "--max-depth") {
        s.budget.max_depth = number;
    } else {
        s.budget.max_drawn_vertices = number;
    }
    return std::nullopt;
}
constexpr char kMaxMemory[] = "--max-memory-mb", kMaxNodes[] = "--max-nodes", kMaxDepth[] = "--max-depth",
               kMaxDrawn[] = "--max-drawn-vertices";

// --runs, --supersampling: one whole number in 1..most.
template <int most>
std::optional<Failure> whole_number(int& slot, const char* name, const std::string& value) {
    const auto number = parse_list<int>(value, [](int v) { return v >= 1 && v <= most; });
    if (!number || number->size() != 1) {
        return usage(std::string(name) + " must be a whole number in 1.." + std::to_string(most) + ", got " +
                     quoted(value));
    }
    slot = number->front();
    return std::nullopt;
}

// "plain|mirror|..." (plan::kAllEffects): the panel's choices for --effect.
const char* effect_choices() {
    static const std::string names = [] {
        std::string text = effect_names();
        for (std::size_t at = text.find(", "); at != std::string::npos; at = text.find(", ", at)) {
            text.replace(at, 2, "|");
        }
        return text;
    }();
    return names.c_str();
}

std::vector<Option> session_rows() {
    const Apply scene = [](Settings& s, const std::string& v) -> std::optional<Failure> {
        s.scene_path = v;
        return std::nullopt;
    };
    const Apply camera = [](Settings& s, const std::string& v) -> std::optional<Failure> {
        s.camera = v;
        return std::nullopt;
    };
    const Apply effects = [](Settings& s, const std::string& v) -> std::optional<Failure> {
        if (v == "all") {
            s.effects.assign(std::begin(plan::kAllEffects), std::end(plan::kAllEffects));
        } else if (const auto effect = plan::parse_effect(v)) {
            s.effects = {*effect};
        } else {
            return usage("unknown effect " + quoted(v) + " (expected " + effect_names() + " or all)");
        }
        return std::nullopt;
    };
    const Apply first_effect = [](Settings& s, const std::string& v) -> std::optional<Failure> {
        const auto effect = plan::parse_effect(v);
        if (!effect) {
            return usage("unknown effect " + quoted(v) + " (expected " + effect_names() + ")");
        }
        s.effects = {*effect};
        return std::nullopt;
    };
    const Apply backend = [](Settings& s, const std::string& v) -> std::optional<Failure> {
        const auto parsed = gl::parse_backend(v);
        if (!parsed) {
            return usage("unknown backend " + quoted(v) + " (expected egl or osmesa)");
        }
        s.backend = *parsed;
        return std::nullopt;
    };
    const Apply depth = [](Settings& s, const std::string& v) -> std::optional<Failure> {
        if (v == "zero_to_one") {
            s.depth = render::DepthPath::ClipControlWhenAvailable;
        } else if (v == "minus_one_to_one") {
            s.depth = render::DepthPath::MinusOneToOne;
        } else {
            return usage("unknown depth range " + quoted(v) + " (expected zero_to_one or minus_one_to_one)");
        }
        return std::nullopt;
    };
    const Apply msaa = [](Settings& s, const std::string& v) -> std::optional<Failure> {
        const auto samples = parse_count(v, kMaxMsaaOption);
        if (!samples) {
            return usage(kMsaaExpected + quoted(v));
        }
        s.msaa_samples = *samples;
        return std::nullopt;
    };
    const Apply out = [](Settings& s, const std::string& v) -> std::optional<Failure> {
        if (v.empty()) {
            return usage("--out needs a folder, got ''");
        }
        s.out_dir = v;
        return std::nullopt;
    };
    const Apply verbose = [](Settings& s, const std::string&) -> std::optional<Failure> {
        s.verbose = true;
        return std::nullopt;
    };
    return {
        {"--scene", "FILE",
         "glTF 2.0 file (.gltf or .glb); default: the showcase,\n" + default_scene() +
             "\n(found through FRUSTUM_ASSETS_DIR, compiled in at build time)",
         scene, kEveryCommand, "scene.gltf", false},
        {"--camera", "NAME|INDEX",
         "camera by name (glTF camera, else its node) or index;\n"
         "default \"main\", else camera 0, else one framing the scene",
         camera, kEveryCommand, "main", false, scene_camera()},
        {"--effect", "E", "plain | mirror | tiles | frustum | curved | lens | nonaffine |\nportal | recursion | all (default all)", effects,
         kRender, "tiles", false},
        {"--effect", "E", "first effect: " + effect_names() + " (default plain)", first_effect, kWindow, "tiles",
         false, choice(effect_choices())},
        {"--size", "WxH",
         "image size in pixels, 1..65536 each (default 640x360); larger\n"
         "than one GPU target holds, a poster: drawn in tiles, streamed to PNG",
         apply_size<render::kMaxPosterSidePx>, kRender, "64x48", false},
        {"--size", "WxH", "image size in pixels, 1..8192 each (default 640x360)", apply_size<kMaxSidePx>, kReports,
         "64x48", false},
        {"--size", "WxH", "window size, 1..8192 each (default 960x540)", apply_size<kMaxSidePx>, kWindow, "64x48",
         false},
        {"--poster-tile", "WxH",
         "render as a poster in tiles of WxH px, 1..8192 each, or auto: the\n"
         "automatic tiles (default: a poster only above one target, in tiles\n"
         "4096 wide, as high as 36 MiB for one tile and one row of tiles allow)",
         apply_poster_tile, kRender, "32x16", false},
        {"--backend", "B", "egl | osmesa (default: egl, falling back to osmesa with a note)", backend, kOffscreen,
         "egl", false},
        {"--depth", "D",
         "zero_to_one: [0, 1] clip depth via clip control when the\n"
         "context has it, else matrices converted to [-1, 1] (default);\n"
         "minus_one_to_one: always the conversion",
         depth, kOffscreen | kWindow, "minus_one_to_one", false, choice("zero_to_one|minus_one_to_one")},
        {"--msaa", "N",
         "multisampled anti-aliasing with N samples per pixel, 1 = off\n"
         "(default 4, or the most the context offers when fewer)",
         msaa, kRender | kWindow, "2", false, slider(1, kMaxMsaaOption, true)},
        {"--out", "DIR", "output folder, created if missing (default out)", out, kOffscreen, "out", false},
        {"--verbose", nullptr, "print the GL context and its KHR_debug messages", verbose, kEveryCommand, nullptr,
         false},
        {"--max-memory-mb", "N",
         "budget for the decoded scene (vertices, indices, images,\n"
         "parsed JSON) and, in render, for the output images of\n"
         "the run (default 256; a render peaks at about 5x the scene's)",
         apply_budget<kMaxMemory>, kEveryCommand, "300", false},
        {"--max-nodes", "N", "most nodes, and most mesh primitives, in the file (default 100000)",
         apply_budget<kMaxNodes>, kEveryCommand, "1000", false},
        {"--max-depth", "N", "longest parent-to-child node chain (default 10000)", apply_budget<kMaxDepth>,
         kEveryCommand, "100", false},
        {"--max-drawn-vertices", "N", "most vertices drawn per frame, over all nodes (default 33554432)",
         apply_budget<kMaxDrawn>, kEveryCommand, "1000000", false},
    };
}

std::vector<Option> window_rows() {
    return {
        {"--context", "C",
         "es: OpenGL ES 3 (default); gl: desktop OpenGL core 4.3+, whose\n"
         "occlusion queries count the fragments of each pass (both through EGL)",
         [](Settings& s, const std::string& v) -> std::optional<Failure> {
             if (v != "es" && v != "gl") {
                 return usage("unknown context " + quoted(v) + " (expected es or gl)");
             }
             s.context_api = v == "es" ? gl::Api::Gles : gl::Api::GlCore;
             return std::nullopt;
         },
         kWindow, "gl", false},
        {"--inset", nullptr, "start with the frustum view inset shown (key F)",
         [](Settings& s, const std::string&) -> std::optional<Failure> {
             s.inset = true;
             return std::nullopt;
         },
         kWindow, nullptr, false},
        {"--panel", nullptr, "start with the control panel shown (key P)",
         [](Settings& s, const std::string&) -> std::optional<Failure> {
             s.panel = true;
             return std::nullopt;
         },
         kWindow, nullptr, false},
        {"--help-overlay", nullptr, "start with the key help shown (key H)",
         [](Settings& s, const std::string&) -> std::optional<Failure> {
             s.help_overlay = true;
             return std::nullopt;
         },
         kWindow, nullptr, false},
        {"--frames", "N", "draw N frames, then exit (for scripts and tests)",
         [](Settings& s, const std::string& v) -> std::optional<Failure> {
             s.frames = parse_count(v, kMaxFrames);
             if (!s.frames) {
                 return usage("--frames must be 1.." + std::to_string(kMaxFrames) + ", got " + quoted(v));
             }
             return std::nullopt;
         },
         kWindow, "3", false},
        {"--screenshot", "FILE", "with --frames: save frame N as PNG (what the window shows)",
         [](Settings& s, const std::string& v) -> std::optional<Failure> {
             if (v.empty()) {
                 return usage("--screenshot needs a file, got ''");
             }
             s.screenshot = v;
             return std::nullopt;
         },
         kWindow, "shot.png", false},
        {"--keys", "LIST",
         "press these keys, one per frame from the first (for tests):\n"
         "e.g. 1,7,Shift+Left,+,H (a character, Left, Right, Up, Down, Esc)",
         [](Settings& s, const std::string& v) -> std::optional<Failure> {
             auto keys = parse_keys(v);
             if (!keys) {
                 return usage("--keys must be a comma-separated list of keys (a character, Left, Right, Up, Down, "
                              "Esc, Shift+KEY), got " + quoted(v));
             }
             s.keys = std::move(*keys);
             return std::nullopt;
         },
         kWindow, "1,Shift+Left,h", false},
    };
}

std::vector<Option> report_rows() {
    const EffectOption* slit = find_effect_option("--slit");
    const EffectOption* pivot = find_effect_option("--pivot");
    return {
        {"--patches", "LIST", "patch grids G to compare, comma-separated, 1..64 (default 1,2,4,8,16)",
         [](Settings& s, const std::string& v) -> std::optional<Failure> {
             auto counts = parse_list<int>(v, [](int g) { return g >= 1 && g <= plan::kMaxCurvedPatches; });
             if (!counts) {
                 return usage("--patches must be a comma-separated list of whole numbers in 1.." +
                              std::to_string(plan::kMaxCurvedPatches) + ", got " + quoted(v));
             }
             s.patch_counts = *counts;
             return std::nullopt;
         },
         kCurvedReport, "1,4", false},
        {"--grids", "LIST", "grid sizes N (N x N tiles), comma-separated (default 4,8,16,32)",
         [](Settings& s, const std::string& v) -> std::optional<Failure> {
             auto grids = parse_list<int>(v, [](int g) { return g >= 1 && g <= kMaxLensGrid; });
             if (!grids) {
                 return usage("--grids must be a comma-separated list of whole numbers in 1.." +
                              std::to_string(kMaxLensGrid) + ", got " + quoted(v));
             }
             s.grids = *grids;
             return std::nullopt;
         },
         kLensReport, "4,8", false},
        {"--supersampling", "K", "reference texture resolution / frame resolution, 1..8 (default 4)",
         [](Settings& s, const std::string& v) { return whole_number<8>(s.supersampling, "--supersampling", v); },
         kLensReport, "2", false},
        {"--runs", "N", "timed repetitions per frame, median reported, 1..100 (default 5)",
         [](Settings& s, const std::string& v) { return whole_number<100>(s.runs, "--runs", v); },
         kLensReport | kNonAffineReport, "3", false},
        {"--edges", "LIST", "subdivision edge lengths in metres, comma-separated, 0 = none\n(default 0,1,0.5,0.25,0.1)",
         [](Settings& s, const std::string& v) -> std::optional<Failure> {
             auto edges = parse_list<float>(v, [](float e) { return e >= 0.0f && e <= 100.0f; });
             if (!edges) {
                 return usage("--edges must be a comma-separated list of lengths in [0, 100] metres, got " +
                              quoted(v));
             }
             s.max_edges_m = *edges;
             return std::nullopt;
         },
         kNonAffineReport, "0,0.5", false},
        // The effect's --slit and --pivot (same bounds and messages), with the report's defaults.
        {"--slit", slit->value, "depth (m) where the left and right planes meet (default 2.6)", slit->apply,
         kNonAffineReport, slit->example, false},
        {"--pivot", pivot->value, "depth (m) where they cut the camera's side planes (default 8)", pivot->apply,
         kNonAffineReport, pivot->example, false},
    };
}

} // namespace

std::string effect_names() {
    std::string names;
    for (std::size_t i = 0; i < std::size(plan::kAllEffects); ++i) {
        names += (i ? ", " : "") + std::string(plan::to_string(plan::kAllEffects[i]));
    }
    return names;
}

Settings defaults(Command command) {
    Settings settings;
    settings.scene_path = default_scene();
    if (command == kWindow) {
        settings.effects = {plan::Effect::Plain};
        settings.width_px = 960;
        settings.height_px = 540;
    } else {
        settings.effects.assign(std::begin(plan::kAllEffects), std::end(plan::kAllEffects));
    }
    return settings;
}

const std::vector<Option>& options() {
    static const std::vector<Option> table = [] {
        std::vector<Option> rows = session_rows();
        for (std::vector<Option> more : {window_rows(), report_rows()}) {
            rows.insert(rows.end(), more.begin(), more.end());
        }
        for (const EffectOption& e : effect_options()) {
            rows.push_back({e.name, e.value, e.help, e.apply, e.commands, e.example, true, e.control});
        }
        return rows;
    }();
    return table;
}

const Option* find_option(Command command, const std::string& name) {
    for (const Option& option : options()) {
        if ((option.commands & command) && option.name == name) {
            return &option;
        }
    }
    return nullptr;
}

std::variant<HelpRequest, Settings, Failure> parse_options(Command command, const std::vector<std::string>& args) {
    Settings settings = defaults(command);
    const std::string hint = help_hint(command);
    for (std::size_t i = 1; i < args.size(); ++i) {
        const std::string& name = args[i];
        if (name == "--help" || name == "-h") {
            return HelpRequest{};
        }
        const Option* option = find_option(command, name);
        if (!option) {
            const bool elsewhere = std::any_of(options().begin(), options().end(),
                                               [&](const Option& o) { return o.name == name; });
            if (elsewhere) {
                return usage(name + " does not apply to " + command_name(command) + hint);
            }
            return usage("unknown option '" + name + "'" +
                         (command == kRender ? std::string() : std::string(" of ") + command_name(command)) + hint);
        }
        if (option->value && i + 1 >= args.size()) {
            return usage(name + " needs a value" + hint);
        }
        const std::string value = option->value ? args[++i] : std::string();
        if (auto failure = option->apply(settings, value)) {
            return *failure;
        }
    }
    if (auto failure = check_effect_settings(settings)) {
        return *failure;
    }
    return settings;
}

std::string options_help(Command command, bool effect_rows) {
    constexpr std::size_t kColumn = 22; // "  --lens-center x,y   "
    std::string text;
    for (const Option& option : options()) {
        if (!(option.commands & command) || option.effect_row != effect_rows) {
            continue;
        }
        std::string head = "  " + option.name + (option.value ? std::string(" ") + option.value : "");
        head.resize(std::max(kColumn, head.size() + 1), ' ');
        std::string help = option.help;
        for (std::size_t at = help.find('\n'); at != std::string::npos; at = help.find('\n', at + 1)) {
            help.insert(at + 1, std::string(kColumn, ' '));
        }
        text += head + help + "\n";
    }
    return text;
}

} // namespace demo
