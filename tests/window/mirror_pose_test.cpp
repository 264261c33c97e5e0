// The mirror's rigid motion and what moves with it.
#include "../plan/showcase.hpp"

#include <doctest/doctest.h>
// Approx epsilon of these float results: 2 float ulps relative (2 x 1.19e-7), doctest's
// default (1.19e-5) being 100; each passes at 2 ulps (measured: tightened until one failed).
static constexpr double kFloatTwoUlps = 2.4e-7;

#include <plan/mirror_motion.hpp>
#include <window/mirror_pose.hpp>

namespace {

glm::vec3 center(const scene::MirrorRect& m) { return m.corner + 0.5f * (m.a1 + m.a2); }

} // namespace

TEST_SUITE("window") {

TEST_CASE("an unmoved pose is the identity motion") {
    const scene::MirrorRect& mirror = *render_test::showcase().mirror;
    const glm::mat4 motion = window::mirror_motion(mirror, window::MirrorPose{});
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            CHECK(motion[c][r] == doctest::Approx(c == r ? 1.0f : 0.0f).epsilon(1e-6));
        }
    }
}

TEST_CASE("turning and tilting keep the centre; sliding and pushing move it along the turned axes") {
    const scene::MirrorRect& mirror = *render_test::showcase().mirror;
    window::MirrorPose pose;
    pose.turn_rad = 0.3f;
    pose.tilt_rad = -0.2f;
    glm::mat4 motion = window::mirror_motion(mirror, pose);
    CHECK(plan::check_rigid_motion(motion, "test").ok());
    const scene::MirrorRect turned = plan::moved_mirror(mirror, motion);
    CHECK(glm::length(center(turned) - center(mirror)) < 1e-5f);
    CHECK(glm::length(turned.a1) == doctest::Approx(glm::length(mirror.a1)).epsilon(kFloatTwoUlps));
    CHECK(glm::length(turned.a2) == doctest::Approx(glm::length(mirror.a2)).epsilon(kFloatTwoUlps));

    pose.slide_m = 0.5f;
    pose.push_m = 0.25f;
    motion = window::mirror_motion(mirror, pose);
    const scene::MirrorRect moved = plan::moved_mirror(mirror, motion);
    const glm::vec3 shift = center(moved) - center(mirror);
    CHECK(glm::dot(shift, glm::normalize(turned.a1)) == doctest::Approx(0.5f).epsilon(1e-4));
    CHECK(glm::dot(shift, glm::normalize(glm::cross(turned.a1, turned.a2))) == doctest::Approx(0.25f).epsilon(1e-4));
}

TEST_CASE("plan::check_rigid_motion names what is wrong") {
    const auto scaled = plan::check_rigid_motion(glm::mat4(2.0f), "where()");
    REQUIRE_FALSE(scaled.ok());
    CHECK(scaled.error().rfind("where(): motion must be rigid (det 1, orthonormal columns, last row 0 0 0 1), got det=8",
                               0) == 0);
    glm::mat4 mirrored(1.0f);
    mirrored[0][0] = -1.0f;
    CHECK_FALSE(plan::check_rigid_motion(mirrored, "where()").ok());
}

TEST_CASE("the showcase's backing board moves with its mirror, nothing else does") {
    const scene::Scene& scene = render_test::showcase();
    const std::vector<int> attached = window::mirror_attachments(scene);
    REQUIRE(attached.size() == 1);
    CHECK(scene.instances[static_cast<std::size_t>(attached[0])].node_name == "mirror_backing");
    scene::Scene no_mirror;
    CHECK(window::mirror_attachments(no_mirror).empty());
}

} // TEST_SUITE
