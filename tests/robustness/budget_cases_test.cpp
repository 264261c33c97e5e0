// Issue 20: hostile but small inputs cost a bounded amount. Each case is a
// small input generated here (the big ones are only big once parsed), run
// through the built frustum-demo / frustum-vectors under an address-space
// limit (setrlimit RLIMIT_AS in the child, what `prlimit --as` does), and
// checked for its message, its exit status and its peak RSS (wait4).
// docs/robustness.md lists the cases with their cost before and after.
#include "support.hpp"

#include <doctest/doctest.h>

#include <sys/stat.h>

#include <filesystem>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

// Every case below runs under this cap; on main several needed 2.5 to 21 GB.
constexpr long kAddressSpaceCap = 2048L << 20; // 2 GiB
// Refused cases stop before anything large is allocated: 200 MiB, or 400
// MiB in an AddressSanitizer build (redzones and the freed-memory
// quarantine about double the heap; the address-space cap is left out
// there, see support.cpp).
constexpr long kRefusedPeakKb = (support::kSanitized ? 400 : 200) * 1024;

std::string asset() { return R"("asset": {"version": "2.0"})"; }

// One accessor without a bufferView (zeros, legal glTF) of `count` VEC3,
// drawn by `primitives` primitives of one mesh on `nodes` nodes.
std::string zero_filled(long count, int primitives, int nodes) {
    std::string prims, node_list, roots;
    for (int p = 0; p < primitives; ++p) prims += std::string(p ? "," : "") + R"({"attributes": {"POSITION": 0}})";
    for (int n = 0; n < nodes; ++n) {
        node_list += std::string(n ? "," : "") + R"({"mesh": 0})";
        roots += (n ? "," : "") + std::to_string(n);
    }
    return "{" + asset() + R"(, "accessors": [{"componentType": 5126, "type": "VEC3", "count": )" +
           std::to_string(count) + R"(, "min": [0,0,0], "max": [0,0,0]}], "meshes": [{"primitives": [)" + prims +
           R"(]}], "nodes": [)" + node_list + R"(], "scenes": [{"nodes": [)" + roots + "]}]}";
}

// n nodes, node i the parent of node i+1 (a chain) or of (i+1) % n (a cycle).
std::string chain(int n, bool cycle) {
    std::string nodes;
    for (int i = 0; i < n; ++i) {
        nodes += i ? "," : "";
        nodes += (i + 1 < n || cycle) ? R"({"children": [)" + std::to_string((i + 1) % n) + "]}" : "{}";
    }
    return "{" + asset() + R"(, "nodes": [)" + nodes + "]}";
}

std::string empty_objects_extras(long count) {
    std::string extras;
    extras.reserve(std::size_t(count) * 3);
    for (long i = 0; i < count; ++i) extras += i ? ",{}" : "{}";
    return "{" + asset() + R"(, "extras": [)" + extras + "]}";
}

#ifdef FRUSTUM_DEMO_EXE
struct Run {
    support::Outcome outcome;
    bool out_exists = false;
};

Run demo(const support::TempDir& dir, const std::string& gltf, std::vector<std::string> options) {
    support::write_file(dir / "scene.gltf", gltf);
    std::vector<std::string> args{"render", "--scene", (dir / "scene.gltf").string(), "--out",
                                  (dir / "out").string()};
    args.insert(args.end(), options.begin(), options.end());
    support::Launch launch;
    launch.args = args;
    launch.address_space_limit_bytes = kAddressSpaceCap;
    Run run;
    run.outcome = support::run(FRUSTUM_DEMO_EXE, launch);
    run.out_exists = fs::exists(dir / "out");
    return run;
}

void check_refused(const Run& run, int status, const std::vector<std::string>& phrases) {
    INFO("stderr: " << run.outcome.err);
    CHECK(run.outcome.signal == 0);
    CHECK(run.outcome.exit_status == status);
    support::check_phrases(run.outcome.err, phrases);
    CHECK(run.outcome.peak_rss_kb < kRefusedPeakKb);
    CHECK_FALSE(run.out_exists); // no new empty folder
    CHECK(run.outcome.err.find('\n') == run.outcome.err.size() - 1); // one line
}

// A plain render at `size` of zero_filled(count, primitives, nodes), refused
// with exit status 1 (check_refused) and `phrases`.
void check_zero_filled_refused(long count, int primitives, int nodes, const std::string& size,
                               const std::vector<std::string>& phrases) {
    support::TempDir dir;
    check_refused(demo(dir, zero_filled(count, primitives, nodes), {"--effect", "plain", "--size", size}), 1, phrases);
}

#endif

} // namespace

#ifdef FRUSTUM_DEMO_EXE
TEST_CASE("budget: zero-filled accessors over the memory budget are refused before decoding") {
    // 318 bytes on main -> 5.5 GB peak RSS: 4 x 16 Mi vertices.
    check_zero_filled_refused(16777216, 4, 1, "64x64",
                              {"the scene decodes to 1 GiB", "over the budget of 256 MiB",
                               "raise it with --max-memory-mb"});
}

TEST_CASE("budget: zero-filled accessors that fit are rendered") {
    support::TempDir dir;
    const Run run = demo(dir, zero_filled(3000, 2, 2), {"--effect", "plain", "--size", "32x32"});
    INFO("stderr: " << run.outcome.err);
    CHECK(run.outcome.exit_status == 0);
    CHECK(fs::exists(dir / "out" / "plain.png"));
}

TEST_CASE("budget: one accessor drawn by many nodes is bounded by --max-drawn-vertices") {
    check_zero_filled_refused(1000000, 1, 40, "64x64",
                              {"the vertex count drawn per frame", "over the limit of 33554432",
                               "raise it with --max-drawn-vertices"});
}

TEST_CASE("budget: node count, chains and cycles cost O(nodes) and a short message") {
    support::TempDir dir;
    SUBCASE("more nodes than --max-nodes: refused while reading the JSON") {
        check_refused(demo(dir, chain(100001, false), {"--effect", "plain"}), 1,
                      {"the file has more than 100000 nodes", "raise it with --max-nodes"});
    }
    SUBCASE("a chain deeper than --max-depth") {
        check_refused(demo(dir, chain(20000, false), {"--effect", "plain"}), 1,
                      {"the node hierarchy depth", "is 10001, over the limit of 10000", "raise it with --max-depth"});
    }
    SUBCASE("a 100000-node cycle: found in one pass, at most 8 links printed") {
        const Run run = demo(dir, chain(100000, true), {"--effect", "plain"});
        check_refused(run, 1, {"the node graph has a cycle of 100000 nodes (parent -> child): 1 -> 2 -> 3"});
        CHECK(run.outcome.err.size() < 400);
    }
}

TEST_CASE("budget: a JSON tree larger than the budget is refused before tinygltf builds it") {
    support::TempDir dir;
    // 2 million "{}" (6 MB of text): a tree of ~300 MB per parse on main.
    check_refused(demo(dir, empty_objects_extras(2000000), {"--effect", "plain"}), 1,
                  {"the JSON holds more than 1677721 values", "raise it with --max-memory-mb"});
}

TEST_CASE("budget: images over the budget are refused before they are decoded") {
    support::TempDir dir;
    // A PNM header claiming 8192x8192 (691 MB on main): not a glTF image format.
    const std::string pnm_uri = "data:image/png;base64,UDYKODE5MiA4MTkyCjI1NQo="; // "P6\n8192 8192\n255\n"
    const std::string gltf = "{" + asset() + R"(, "images": [{"uri": ")" + pnm_uri +
                             R"("}], "textures": [{"source": 0}]})"; // drawn: an undrawn image is not decoded
    check_refused(demo(dir, gltf, {"--effect", "plain"}), 1, {"image 0: the image is neither PNG nor JPEG"});
}

TEST_CASE("budget: output images and tiles are bounded before rendering") {
    support::TempDir dir;
    SUBCASE("8192x8192 with every effect: 5.7 GB and a stb overflow on main") {
        check_refused(demo(dir, zero_filled(3, 1, 1), {"--size", "8192x8192"}), 2,
                      {"--size 8192x8192 with 9 effect(s) holds", "over the budget of 256 MiB",
                       "raise it with --max-memory-mb"});
    }
    SUBCASE("--tiles 8192x8192: 10.6 GB in 90 s on main") {
        check_refused(demo(dir, zero_filled(3, 1, 1), {"--effect", "tiles", "--size", "8192x8192", "--tiles",
                                                        "8192x8192"}),
                      2, {"--tiles 8192x8192 is 67108864 tiles, over the limit of 16384"});
    }
}

TEST_CASE("failed runs leave no new folder; help-valid lens values work; --sagitta is bounded") {
    support::TempDir dir;
    SUBCASE("--camera nosuch") {
        support::Launch launch;
        launch.args = {"render", "--camera", "nosuch", "--effect", "plain", "--out", (dir / "new" / "dir").string()};
        const support::Outcome outcome = support::run(FRUSTUM_DEMO_EXE, launch);
        CHECK(outcome.exit_status == 2);
        CHECK_FALSE(fs::exists(dir / "new"));
    }
    SUBCASE("--sagitta 1e30 with an effect that does not use it") {
        support::Launch launch;
        launch.args = {"render", "--sagitta", "1e30", "--effect", "plain", "--size", "32x32", "--out",
                       (dir / "out").string()};
        const support::Outcome outcome = support::run(FRUSTUM_DEMO_EXE, launch);
        CHECK(outcome.exit_status == 2);
        CHECK(outcome.err.find("frustum-demo: error: --sagitta 1e+30 must be in [0, ") !=
              std::string::npos);
        CHECK_FALSE(fs::exists(dir / "out"));
    }
    SUBCASE("the largest --lens-power and --lens-grid the help calls valid") {
        support::Launch launch;
        launch.args = {"render", "--effect", "lens", "--lens-power", "2", "--lens-grid", "128", "--size", "256x256",
                       "--out", (dir / "out").string()};
        const support::Outcome outcome = support::run(FRUSTUM_DEMO_EXE, launch);
        INFO("stderr: " << outcome.err);
        CHECK(outcome.exit_status == 0);
        support::Launch beyond = launch;
        beyond.args[4] = "2.5";
        CHECK(support::run(FRUSTUM_DEMO_EXE, beyond).err.find("--lens-power must be a number in (0, 2]") !=
              std::string::npos);
    }
}

TEST_CASE("window --screenshot / write_png refuse to replace what is not a regular file") {
    support::TempDir dir;
    const fs::path fifo = dir / "fifo.png";
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    fs::create_directory(dir / "out");
    fs::create_symlink(fifo, dir / "out" / "plain.png");
    support::Launch launch;
    launch.args = {"render", "--effect", "plain", "--size", "16x16", "--out", (dir / "out").string()};
    const support::Outcome outcome = support::run(FRUSTUM_DEMO_EXE, launch);
    INFO("stderr: " << outcome.err);
    CHECK(outcome.exit_status == 1);
    CHECK(outcome.err.find("is a symbolic link, not a regular file; refusing to replace it") != std::string::npos);
    CHECK(fs::is_symlink(dir / "out" / "plain.png"));
}
#endif

#ifdef FRUSTUM_VECTORS_EXE
TEST_CASE("budget: frustum-vectors refuses a document of a million values without building it") {
    std::string text = "[";
    for (int i = 0; i < 1100000; ++i) text += i ? ",{}" : "{}";
    text += "]";
    support::Launch launch;
    launch.stdin_text = text;
    launch.address_space_limit_bytes = kAddressSpaceCap;
    const support::Outcome outcome = support::run(FRUSTUM_VECTORS_EXE, launch);
    INFO("stderr: " << outcome.err);
    CHECK(outcome.exit_status == 2);
    CHECK(outcome.err.find("more than 1000000 values") != std::string::npos);
    CHECK(outcome.peak_rss_kb < kRefusedPeakKb);
}
#endif
