// Outcomes -> the response document of docs/vectors-contract.md.
#pragma once

#include "vectors/evaluate.hpp"

#include <nlohmann/json.hpp>

#include <vector>

namespace vectors {

// {"cases": [...]} with, per case and in this order: id, ok, then either
// error, or matrix, inverse (16 numbers each, column-major as GLM stores
// them), planes {left, right, bottom, top, near, far (null when infinite)},
// corners (8 x [x, y, z, w]), center, vanishing {O, O1, O2}, valid, and
// clip, inside when the case had points.
nlohmann::ordered_json response_json(const std::vector<Outcome>& outcomes);

} // namespace vectors
