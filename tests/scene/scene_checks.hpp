// Checks shared by the scene suite's model tests (models_test.cpp on the
// generated models, samples_test.cpp on the external samples, and the
// external-files tests): load or fail the test, compare within a stated
// tolerance, find an instance by its node's name.
#pragma once

#include "scene/load_gltf.hpp"

#include <doctest/doctest.h>

#include <glm/glm.hpp>

#include <cmath>
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

inline const scene::Instance& instance_named(const scene::Scene& s, const std::string& name) {
    for (const scene::Instance& instance : s.instances) {
        if (instance.node_name == name) return instance;
    }
    FAIL("no instance named " << name);
    return s.instances.front();
}

} // namespace scene_test
