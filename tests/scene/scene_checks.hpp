// Checks shared by the scene suite's model tests (models_test.cpp on the
// generated models, samples_test.cpp on the external samples, and the
// external-files tests): load or fail the test, compare within a stated
// tolerance, find an instance by its node's name.
#pragma once

#include "scene/load_gltf.hpp"

#include <doctest/doctest.h>

#include <glm/glm.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

namespace scene_test {

inline scene::Scene load_ok(const std::string& path, const scene::LoadOptions& options = {}) {
    frustum::Result<scene::Scene> result = scene::load_gltf(path, options);
    INFO(result.error());
    REQUIRE(result.ok());
    return std::move(result).value();
}

inline bool near(const glm::vec3& a, const glm::vec3& b, float tolerance) {
    return glm::all(glm::lessThanEqual(glm::abs(a - b), glm::vec3(tolerance)));
}

inline bool near(const glm::mat4& a, const glm::mat4& b, float tolerance) {
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            if (std::abs(a[c][r] - b[c][r]) > tolerance) return false;
        }
    }
    return true;
}

// What every loaded scene must be: `meshes`, `instances`, `cameras` and
// `images` of each, no mirror or lens node, and every primitive drawable
// (positions and indices, attributes of the positions' count, indices in range).
struct Counts {
    std::size_t meshes, instances, cameras, images;
};

inline void check_loaded_shape(const scene::Scene& s, const Counts& expected) {
    CHECK(s.meshes.size() == expected.meshes);
    CHECK(s.instances.size() == expected.instances);
    CHECK(s.cameras.size() == expected.cameras);
    CHECK(s.images.size() == expected.images);
    CHECK_FALSE(s.mirror.has_value());
    CHECK_FALSE(s.lens.has_value());
    for (const scene::Mesh& mesh : s.meshes) {
        for (const scene::Primitive& primitive : mesh.primitives) {
            CHECK_FALSE(primitive.positions.empty());
            CHECK_FALSE(primitive.indices.empty());
            CHECK((primitive.normals.empty() || primitive.normals.size() == primitive.positions.size()));
            CHECK((primitive.colors.empty() || primitive.colors.size() == primitive.positions.size()));
            CHECK((primitive.texcoords.empty() || primitive.texcoords.size() == primitive.positions.size()));
            for (std::uint32_t index : primitive.indices) {
                REQUIRE(index < primitive.positions.size());
            }
        }
    }
}

// A model of a count table: its file (or sample) name and what it loads as.
struct ExpectedModel {
    const char* name;
    Counts counts;
};

// Loads `path` (load_ok) and checks it against `expected` (check_loaded_shape).
inline scene::Scene load_with_shape(const std::string& path, const Counts& expected) {
    scene::Scene s = load_ok(path);
    check_loaded_shape(s, expected);
    return s;
}

// REQUIREs that the scene holds one image, and CHECKs that it is
// width x height pixels decoded to RGBA8 (4 bytes a pixel).
inline void check_one_image(const scene::Scene& s, int width, int height) {
    REQUIRE(s.images.size() == 1);
    CHECK(s.images[0].width == width);
    CHECK(s.images[0].height == height);
    CHECK(s.images[0].rgba.size() == std::size_t(width) * std::size_t(height) * 4u);
}

inline const scene::Instance& instance_named(const scene::Scene& s, const std::string& name) {
    for (const scene::Instance& instance : s.instances) {
        if (instance.node_name == name) return instance;
    }
    FAIL("no instance named " << name);
    return s.instances.front();
}

} // namespace scene_test
