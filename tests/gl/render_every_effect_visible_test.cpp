// Every effect visible (issue 33): on every generated model (the room and
// the street seen from inside, the cameras without a usable far plane
// included) and the showcase, with every parameter derived, mirror, curved,
// portal and recursion each change at least 1% of the frame against plain,
// and lens and nonaffine render and change it (every_effect_check.hpp).
// 160x90, one backend.
#include "../sample_files.hpp"
#include "every_effect_check.hpp"

TEST_SUITE("gl") {

TEST_CASE("every effect visible on every generated model and the showcase, the room and the street from inside") {
    const auto files = test_samples::scene_files();
    bool has_room = false, has_street = false;
    for (const auto& file : files) {
        has_room = has_room || file.filename() == "room_no_zfar.gltf";
        has_street = has_street || file.filename() == "street.gltf";
    }
    REQUIRE(has_room);
    REQUIRE(has_street);
    const auto short_of = every_effect::check_files(files, true);
    CHECK(short_of.empty());
}

} // TEST_SUITE
