// Where the user has moved the planar mirror (arrow keys), as a rigid world
// motion for render::Renderer::move_mirror(), and which other instances
// travel with it. Pure math: no GL.
#pragma once

#include <scene/scene.hpp>

#include <glm/glm.hpp>

#include <vector>

namespace window {

// Relative to where the scene put the mirror; all zero = unmoved.
struct MirrorPose {
    float turn_rad = 0.0f; // about world +Y through the mirror's centre
    float tilt_rad = 0.0f; // about its first edge a1 through its centre (applied first)
    float slide_m = 0.0f;  // along the turned a1
    float push_m = 0.0f;   // along the turned reflecting normal

    bool operator==(const MirrorPose& other) const;
    bool operator!=(const MirrorPose& other) const { return !(*this == other); }
};

// The motion taking the scene's mirror to `pose`, with c its centre and
// n = normalize(a1 x a2):
//   T(c + slide R a1/|a1| + push R n) * R * T(-c),  R = turn(+Y) * tilt(a1).
glm::mat4 mirror_motion(const scene::MirrorRect& mirror, const MirrorPose& pose);

// Instances that belong to the mirror besides its surface (a backing board,
// a frame): every vertex within 5% of the mirror's longer edge of its plane
// and inside the rectangle grown by that margin. The surface itself
// (mirror.instance) is not listed. Empty when the scene has no mirror.
std::vector<int> mirror_attachments(const scene::Scene& scene);

} // namespace window
