// stb_easy_font text as triangles: placement, columns, flipping y.
#include <doctest/doctest.h>
// Approx epsilon of these float results: 2 float ulps relative (2 x 1.19e-7), doctest's
// default (1.19e-5) being 100; each passes at 2 ulps (measured: tightened until one failed).
static constexpr double kFloatTwoUlps = 2.4e-7;

#include <window/text_layout.hpp>

#include <algorithm>

namespace {

struct Box {
    glm::vec2 min{1e9f}, max{-1e9f};
};

Box box_of(const std::vector<glm::vec3>& vertices) {
    Box box;
    for (const glm::vec3& v : vertices) {
        box.min = glm::min(box.min, glm::vec2(v));
        box.max = glm::max(box.max, glm::vec2(v));
    }
    return box;
}

} // namespace

TEST_SUITE("window") {

TEST_CASE("glyphs become whole triangles inside the reported block, y counted from the bottom") {
    const window::TextLayout layout = window::layout_text({"Hello", "W"}, glm::vec2(10.0f, 20.0f), 2.0f, 200);
    REQUIRE_FALSE(layout.triangles.empty());
    CHECK(layout.triangles.size() % 6 == 0); // two triangles per stb quad
    CHECK(layout.size_px.y == doctest::Approx(2.0f * 2.0f * window::kLineHeightDots).epsilon(kFloatTwoUlps));
    const Box box = box_of(layout.triangles);
    CHECK(box.min.x >= 10.0f);
    CHECK(box.max.x <= 10.0f + layout.size_px.x);
    CHECK(box.max.y <= 200.0f - 20.0f); // the top-left corner is 20 px below the top
    CHECK(box.min.y >= 200.0f - 20.0f - layout.size_px.y);
    for (const glm::vec3& v : layout.triangles) {
        CHECK(v.z == 0.0f);
    }
}

TEST_CASE("a tab starts a second column aligned over all lines") {
    const window::TextLayout one = window::layout_text({"a\tx", "abcdefgh\tx"}, glm::vec2(0.0f), 1.0f, 100);
    const window::TextLayout first_x = window::layout_text({"a\tx"}, glm::vec2(0.0f), 1.0f, 100);
    const window::TextLayout second_x = window::layout_text({"abcdefgh\tx"}, glm::vec2(0.0f), 1.0f, 100);
    // Both x's start after the widest first column.
    CHECK(one.size_px.x == doctest::Approx(second_x.size_px.x).epsilon(kFloatTwoUlps));
    CHECK(first_x.size_px.x < second_x.size_px.x);
    CHECK(window::layout_text({}, glm::vec2(0.0f), 1.0f, 100).triangles.empty());
    CHECK(window::layout_text({"", " "}, glm::vec2(0.0f), 1.0f, 100).triangles.empty());
}

} // TEST_SUITE
