// A request's camera -> the library's matrix pair (before view and ops).
#pragma once

#include "vectors/request.hpp"

#include <frustum/matrix_pair.hpp>
#include <frustum/result.hpp>

namespace vectors {

// The JSON name of the camera kind: "perspective", "planes", ...
const char* camera_name(const Camera& camera);

// One library constructor per kind, in double:
//   perspective -> frustum::perspective (fovy_deg * pi / 180, VERTICAL fov)
//   frustum     -> frustum::off_axis        ortho -> frustum::orthographic
//   planes      -> frustum::from_planes (far_point) or
//                  frustum::from_planes_volume_growth (far: "volume")
//   mirror_rect -> frustum::mirror_rectangle (MirrorFit::Paper / Exact)
//   matrix      -> frustum::from_matrix (the one numeric inversion)
// The error is the library's sentence, unchanged.
frustum::Result<frustum::MatrixPair<double>> make_camera(const Camera& camera, frustum::DepthRange depth);

} // namespace vectors
