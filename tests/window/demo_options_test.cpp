// frustum-demo's one option table (app/demo/options.hpp), walked row by row:
// every command that declares an option accepts the row's example and
// answers every bad value the same way; the commands that do not declare it
// refuse it with one line naming it; --verbose and the budget options are
// accepted everywhere; each command's --help lists exactly its rows.
#include "process.hpp"

#include <doctest/doctest.h>

#include <demo/options.hpp>

#include <map>
#include <set>
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

const std::vector<std::string> kBadValues = {"", "0", "-1", "x!", "1e30", "3,", "0x0"};

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
        CHECK(outcome(command, {"--tiles", "128x128"}) == "ok");
        CHECK(outcome(command, {"--tiles", "129x128"}) ==
              "error: --tiles 129x128 is 16512 tiles, over the limit of 16384");
        CHECK(outcome(command, {"--tiles", "8193x1"}).find("--tiles must be NxM") != std::string::npos);
    }
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
