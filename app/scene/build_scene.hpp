// A validated tinygltf model -> scene::Scene (the only place that converts).
#pragma once

#include "scene/load_gltf.hpp"
#include "scene/scene.hpp"

#include <frustum/result.hpp>

#include <tiny_gltf.h>

namespace scene::detail {

// Precondition: validate_model(model) passed. Still checks what only the
// data can tell: index values, sparse indices, finite positions, and
// degenerate transforms of cameras, "mirror" and "lens". Takes the decoded
// images out of `model` instead of copying them.
frustum::Result<Scene> build_scene(tinygltf::Model&& model, const LoadOptions& options);

} // namespace scene::detail
