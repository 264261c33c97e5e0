// JSON tree -> typed Request, checking the shape of the document only
// (keys, types, array lengths); geometry is left to the library.
#pragma once

#include "vectors/request.hpp"

#include <frustum/result.hpp>

#include <nlohmann/json.hpp>

namespace vectors {

// Fails on the first problem with a message that names its place, e.g.
//   "cases[2].camera.perspective.fovy_deg: expected a number, got string"
//   "cases[0].camera.perspective.fov: unknown key (expected one of fovy_deg, aspect, near, far)"
//   "cases[1].ops[0].crop.height: missing required key"
// Rules beyond plain types (all are exit-2 errors of the tool):
//   - every key is checked: unknown keys are errors at every level;
//   - "id" (string) and "camera" are required; "depth" defaults to zero_to_one;
//   - "camera" and each op hold exactly one kind;
//   - "far" of perspective/frustum is required, null meaning infinite;
//   - a "view" with a world-space camera (planes, mirror_rect, matrix) is an error;
//   - "NaN" or "Infinity" as strings are wrong types (a number overflowing a
//     double, e.g. 1e999, is a number: infinity).
frustum::Result<Request> parse_request(const nlohmann::json& document);

} // namespace vectors
