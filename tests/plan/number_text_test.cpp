// plan::number_text (app/plan/number_text.hpp): labels and messages with
// three significant digits; with a scale, rounding noise prints as 0 (the
// contact sheet's lens caption printed a centre on the view axis, computed
// in float, as "2.23e-08,-2.48e-08").
#include <doctest/doctest.h>

#include <plan/number_text.hpp>

TEST_SUITE("plan") {

TEST_CASE("number_text with a scale prints rounding noise as 0 and keeps the rest") {
    CHECK(plan::number_text(2.23e-08) == "2.23e-08");
    CHECK(plan::number_text(2.23e-08, 1.0) == "0");
    CHECK(plan::number_text(-2.48e-08, 1.0) == "0"); // not "-0"
    CHECK(plan::number_text(0.25, 1.0) == "0.25");
    CHECK(plan::number_text(-0.001, 1.0) == "-0.001");       // above 1e-4 of the scale: shown
    CHECK(plan::number_text(2.23e-08, 1e-6) == "2.23e-08");   // small among small numbers: shown
    CHECK(plan::number_text(-3.0e-05, -1.0) == "0");          // the scale's sign does not matter
}

} // TEST_SUITE
