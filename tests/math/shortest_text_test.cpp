// The portable number formatting (frustum/detail/shortest_text.hpp) gives
// exactly std::to_chars's shortest round-trip text: checked against fixed
// texts everywhere, and against std::to_chars itself wherever the standard
// library implements it for float and double.
#include "support.hpp"

#include "frustum/detail/shortest_text.hpp"

#include <charconv>
#include <cstring>
#include <limits>

using frustum::detail::shortest_text_portable;

namespace {

#if defined(__cpp_lib_to_chars) && __cpp_lib_to_chars >= 201611L
template <class T>
std::string to_chars_text(T value) {
    char buffer[64];
    return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}

template <class T, class Bits>
void check_against_to_chars(Bits seed) {
    mtest::Random rng(seed);
    int mismatches = 0;
    const auto check = [&](T value) {
        const std::string expected = to_chars_text(value), got = shortest_text_portable(value);
        if (expected != got && ++mismatches <= 10) {
            FAIL_CHECK("to_chars gives " << expected << ", the portable path " << got);
        }
    };
    // Random bit patterns: every exponent, subnormals, NaNs and infinities.
    for (int i = 0; i < 20000; ++i) {
        const Bits bits = static_cast<Bits>(rng.bits());
        T value;
        std::memcpy(&value, &bits, sizeof value);
        check(value);
    }
    // Powers of two and their neighbours (a lopsided round-trip interval).
    for (int e = std::numeric_limits<T>::min_exponent - std::numeric_limits<T>::digits;
         e <= std::numeric_limits<T>::max_exponent; ++e) {
        const T p = std::ldexp(T(1), e);
        check(p);
        check(std::nextafter(p, T(0)));
        check(std::nextafter(p, std::numeric_limits<T>::infinity()));
    }
    // Whole numbers and short decimals, where fixed and scientific compete.
    for (int i = -3000; i <= 3000; ++i) {
        for (const T scale : {T(1), T(1e-3), T(1e-7), T(1e7), T(1e12), T(1e20)}) {
            check(T(i) * scale);
        }
    }
    CHECK(mismatches == 0);
}
#endif

} // namespace

TEST_SUITE("math") {

TEST_CASE("the portable shortest text matches std::to_chars's format") {
    // Texts std::to_chars writes (C++17 [charconv.to.chars]): fewest digits,
    // fixed unless scientific is shorter.
    CHECK(shortest_text_portable(100.0) == "100");
    CHECK(shortest_text_portable(1e20) == "1e+20");
    CHECK(shortest_text_portable(123456.0) == "123456");
    CHECK(shortest_text_portable(0.001) == "0.001");
    CHECK(shortest_text_portable(1e-5) == "1e-05");
    CHECK(shortest_text_portable(-0.1) == "-0.1");
    CHECK(shortest_text_portable(0.1f) == "0.1");
    CHECK(shortest_text_portable(1.0 / 3) == "0.3333333333333333");
    CHECK(shortest_text_portable(1.0f / 3) == "0.33333334");
    CHECK(shortest_text_portable(397605984.0f) == "397605984"); // whole numbers exactly
    CHECK(shortest_text_portable(std::numeric_limits<double>::max()) == "1.7976931348623157e+308");
    CHECK(shortest_text_portable(std::numeric_limits<float>::max()) == "3.4028235e+38");
    CHECK(shortest_text_portable(std::numeric_limits<double>::denorm_min()) == "5e-324");
    CHECK(shortest_text_portable(std::numeric_limits<float>::denorm_min()) == "1e-45");
    CHECK(shortest_text_portable(std::ldexp(1.0, -1074 + 52)) == "2.2250738585072014e-308");
    CHECK(shortest_text_portable(9007199254740993.0) == "9007199254740992"); // 2^53 + 1 rounds to 2^53
    CHECK(shortest_text_portable(0.0) == "0");
    CHECK(shortest_text_portable(-0.0) == "-0");
    CHECK(shortest_text_portable(std::numeric_limits<double>::infinity()) == "inf");
    CHECK(shortest_text_portable(-std::numeric_limits<float>::infinity()) == "-inf");
    CHECK(shortest_text_portable(std::numeric_limits<double>::quiet_NaN()) == "nan");
    CHECK(shortest_text_portable(-std::numeric_limits<double>::quiet_NaN()) == "-nan");
}

#if defined(__cpp_lib_to_chars) && __cpp_lib_to_chars >= 201611L
TEST_CASE("the portable shortest text equals std::to_chars for double") {
    check_against_to_chars<double, std::uint64_t>(7001);
}

TEST_CASE("the portable shortest text equals std::to_chars for float") {
    check_against_to_chars<float, std::uint32_t>(7002);
}
#endif

} // TEST_SUITE
