// Result<T> and Status: the accessors that keep a failed result from being
// read as a value. A misuse aborts with one line on stderr (checked in a
// child process where fork() exists, tests/support's runner with its
// timeout), the rest are plain value checks.
#include "support.hpp"

#if defined(__unix__) && !defined(__EMSCRIPTEN__)
#include <support/child_process.hpp>

#include <csignal>
#define MTEST_HAS_FORK 1
#else
#define MTEST_HAS_FORK 0
#endif

#include <functional>
#include <string>

using frustum::Error;
using frustum::Result;
using frustum::Status;

namespace {

Result<int> parsed(bool ok) {
    if (ok) {
        return 7;
    }
    return Error{"frustum::parse(): needs a digit, got x"};
}

// A caller of another Result type, written the way the library writes them.
Result<std::string> caller(bool ok) {
    auto v = parsed(ok);
    if (!v) {
        return v.take_error_in("app::caller()");
    }
    return std::to_string(*v);
}

#if MTEST_HAS_FORK
struct Death {
    bool aborted = false;
    std::string stderr_text;
};

// Runs `body` in a child (tests/support's runner: at most 60 s, then a
// failure naming `what`); reports whether it died of SIGABRT and what it
// wrote to stderr.
Death run_in_child(const std::string& what, const std::function<void()>& body) {
    const support::Outcome child = support::run_function(what, [&body] {
        body();
        return std::string(); // the misuse did not stop the program: the parent sees exit 0
    }, 60);
    Death death;
    death.stderr_text = child.err;
    // Under qemu-user (make test-arm) the emulator adds its own line about
    // the signal to the child's stderr: not the program's output.
    const std::string qemu_note = "qemu: uncaught target signal";
    if (const std::size_t at = death.stderr_text.find(qemu_note); at != std::string::npos) {
        const std::size_t end = death.stderr_text.find('\n', at);
        death.stderr_text.erase(at, end == std::string::npos ? std::string::npos : end - at + 1);
    }
    death.aborted = child.signal == SIGABRT;
    return death;
}
#endif

} // namespace

TEST_CASE("Result: value, value_or and the error of a success and a failure") {
    const auto good = parsed(true);
    const auto bad = parsed(false);
    CHECK(good.ok());
    CHECK(*good == 7);
    CHECK(good.value() == 7);
    CHECK(good.value_or(-1) == 7);
    CHECK(good.error().empty());
    CHECK_FALSE(bad.ok());
    CHECK(bad.value_or(-1) == -1);
    CHECK(bad.error() == "frustum::parse(): needs a digit, got x");
    CHECK(parsed(false).value_or(3) == 3); // the rvalue overload
}

TEST_CASE("Result: take_error moves the error out, take_error_in prefixes the caller") {
    auto bad = parsed(false);
    const Error taken = bad.take_error();
    CHECK(taken.message == "frustum::parse(): needs a digit, got x");
    CHECK(bad.error().empty());
    CHECK_FALSE(bad.ok()); // still a failure, only its text was moved
    const auto relayed = caller(false);
    REQUIRE_FALSE(relayed.ok());
    CHECK(relayed.error() == "app::caller(): frustum::parse(): needs a digit, got x");
    CHECK(*caller(true) == "7");
}

TEST_CASE("Status: take_error and take_error_in like Result") {
    Status failed = Error{"frustum::check(): bad"};
    Status copy = failed;
    CHECK(failed.take_error_in("x()").message == "x(): frustum::check(): bad");
    CHECK(copy.take_error().message == "frustum::check(): bad");
    CHECK(Status().ok());
}

TEST_CASE("Result: -> reads a member of the value") {
    const Result<std::string> text = std::string("abc");
    CHECK(text->size() == 3);
}

#if MTEST_HAS_FORK
TEST_CASE("Result: reading a failed result aborts with its error on stderr") {
    const auto value = run_in_child("bad.value()", [] {
        const auto bad = parsed(false);
        std::printf("%d", bad.value());
    });
    CHECK(value.aborted);
    CHECK(value.stderr_text ==
          "frustum::Result: value() of a failed result: frustum::parse(): needs a digit, got x\n");

    const auto star = run_in_child("*bad", [] {
        auto bad = parsed(false);
        std::printf("%d", *bad);
    });
    CHECK(star.aborted);
    const auto arrow = run_in_child("bad->size()", [] {
        const Result<std::string> bad = Error{"frustum::f(): no"};
        std::printf("%zu", bad->size());
    });
    CHECK(arrow.aborted);
    CHECK(arrow.stderr_text == "frustum::Result: value() of a failed result: frustum::f(): no\n");

    const auto taken = run_in_child("good.take_error()", [] {
        auto good = parsed(true);
        std::printf("%s", good.take_error().message.c_str());
    });
    CHECK(taken.aborted);
    CHECK(taken.stderr_text == "frustum::Result: take_error() of a successful result\n");
    const auto status = run_in_child("Status{}.take_error()", [] {
        Status fine;
        std::printf("%s", fine.take_error().message.c_str());
    });
    CHECK(status.aborted);
    CHECK(status.stderr_text == "frustum::Result: take_error() of a successful status\n");
}
#endif
