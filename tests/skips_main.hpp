// The main of a doctest suite whose checks can be skipped (skips.hpp):
// include it in exactly one file of the suite, instead of defining
// DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN. Exit status: doctest's own when a
// check failed or only options were asked for (--help, --list-test-cases),
// else kSkipExitCode when a check was skipped (each listed, with its
// reason), else 0. With --order-by=rand it prints the seed first, so a
// failing order can be rerun (--rand-seed=N).
#pragma once

#define DOCTEST_CONFIG_IMPLEMENT
#include "skips.hpp"

#include <doctest/doctest.h>

#include <cstdio>

namespace test_skips {

// Keeps current_test_case() up to date and prints the seed of a random order.
struct SkipListener : doctest::IReporter {
    explicit SkipListener(const doctest::ContextOptions&) {}
    void report_query(const doctest::QueryData&) override {}
    void test_run_start() override {
        const doctest::ContextOptions* options = doctest::getContextOptions();
        if (options != nullptr && options->order_by.compare("rand", false) == 0) {
            std::printf("test order: random, --rand-seed=%u\n", options->rand_seed);
            std::fflush(stdout);
        }
    }
    void test_run_end(const doctest::TestRunStats&) override {}
    void test_case_start(const doctest::TestCaseData& test) override { current_test_case() = test.m_name; }
    void test_case_reenter(const doctest::TestCaseData&) override {}
    void test_case_end(const doctest::CurrentTestCaseStats&) override {}
    void test_case_exception(const doctest::TestCaseException&) override {}
    void subcase_start(const doctest::SubcaseSignature&) override {}
    void subcase_end() override {}
    void log_assert(const doctest::AssertData&) override {}
    void log_message(const doctest::MessageData&) override {}
    void test_case_skipped(const doctest::TestCaseData&) override {}
};
REGISTER_LISTENER("skips", 1, SkipListener);

} // namespace test_skips

int main(int argc, char** argv) {
    doctest::Context context(argc, argv);
    const int status = context.run();
    if (context.shouldExit() || status != 0) {
        return status;
    }
    const auto& skipped = test_skips::skipped();
    if (skipped.empty()) {
        return 0;
    }
    std::printf("%zu check(s) SKIPPED, so the suite reports a skip (exit %d), not a pass:\n", skipped.size(),
                test_skips::kSkipExitCode);
    for (const std::string& line : skipped) {
        std::printf("  %s\n", line.c_str());
    }
    return test_skips::kSkipExitCode;
}
