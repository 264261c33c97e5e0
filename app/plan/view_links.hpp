// Mirrors and portals for the portal and recursion effects, placed beside
// any scene's model by its bounds (docs/portals.md, the rule of
// docs/any-scene.md: derived from the bounds, so a default never fails),
// and the small scene of their quads. Pure: no GL.
#pragma once

#include <frustum/matrix_pair.hpp>
#include <frustum/queries.hpp>
#include <frustum/plane.hpp>
#include <frustum/result.hpp>
#include <frustum/rigid.hpp>
#include <scene/scene.hpp>

#include <glm/glm.hpp>

#include <optional>
#include <string_view>
#include <vector>

namespace plan {

// One surface a view passes through. A mirror: entry = the mirror's frame,
// the view is frustum::mirror(camera, plane). A portal: the view through
// entry comes out of exit's front, frustum::portal(camera, entry, exit).
struct ViewLink {
    enum class Kind { Mirror, Portal };
    Kind kind = Kind::Mirror;
    frustum::Frame<float> entry;     // the surface the camera looks into (front = normal side)
    frustum::Frame<float> exit;      // portal only
    float half_width_m = 0.5f;       // of both quads, along the frames' x
    float half_height_m = 0.5f;      // along y
    int surface_instance = -1;       // in link_scene(): the entry quad, drawn with the view's texture
    int exit_instance = -1;          // portal: the exit quad
    int frame_instance = -1;         // portal: a dark frame just behind the entry quad

    // The entry quad's corners, counter-clockwise seen from its front.
    std::vector<glm::vec3> quad() const;
    // The plane the view's near plane lies on, positive where the view sees:
    // the mirror plane, or the exit plane of a portal.
    frustum::Plane<float> near_plane() const;
};

// Which links the recursion effect passes through (--recursion-links).
enum class LinkSet {
    Mirrors, // two facing mirrors, left and right of the model
    Portals, // a portal pair facing itself: its entry on the right, its exit on the left facing it
};
std::string_view to_string(LinkSet set);
std::optional<LinkSet> parse_link_set(std::string_view text);

// Placement follows the camera like every derived parameter
// (docs/any-scene.md): with E the eye, f the viewing direction, R the
// horizontal right (f x +Y; the near plane's x when f is vertical), U = +Y
// (or the near plane's y), d = dot(c - E, f) the depth of the model's
// centre c, or with the eye inside the bounds (a room, a street) half the
// depth of what the middle half of the frame sees first (3 x 3 rays against
// the instances' world boxes, instance_boxes(), and the bounds); at least
// twice the near distance; s_x, s_y the frame's half width and height at depth d, the
// anchor is A = E + d f, on the view axis.
// Errors: a camera without a finite eye (orthographic).
struct ViewAnchor {
    glm::vec3 eye, forward, right, up, point; // E, f along the horizontal, R, U, A
    glm::vec3 view_forward, view_up;          // f itself and R x f: the view's own frame (up tilted with the pitch)
    float near_m = 0.0f, depth_m = 0.0f, half_width_m = 0.0f, half_height_m = 0.0f; // n, d, s_x, s_y
    bool inside = false;                      // the eye is inside the bounds
};
frustum::Result<ViewAnchor> view_anchor(const frustum::MatrixPair<float>& camera, const scene::Bounds& bounds,
                                        const std::vector<scene::Bounds>& boxes, const char* where);

// The world box of each instance's mesh (its positions' box through the
// instance's world matrix), for view_anchor()'s rays.
std::vector<scene::Bounds> instance_boxes(const scene::Scene& scene);

// The point is strictly inside the box.
bool eye_inside(const glm::vec3& eye, const scene::Bounds& bounds);

// The portal effect's pair: the entry at A + 0.5 s_x R, facing the camera,
// 0.4 s_y half high and 0.3 s_y half wide; the exit as large at
// A - 0.6 s_x R, facing R: through the entry the model is seen from its left.
frustum::Result<std::vector<ViewLink>> place_portal_pair(const frustum::MatrixPair<float>& camera,
                                                         const scene::Bounds& bounds,
                                                         const std::vector<scene::Bounds>& boxes = {});

// The recursion effect's links: two mirrors 0.45 s_x either side of the
// view axis facing each other (+R and -R), from depth 0.2 d to 6 d along the
// axis (2 d, the bounds' wall, with the eye inside; to 95% of the far
// distance when that is nearer) and 0.6 s_y half
// high, their quads along f and R x f (so they frame a view that looks down
// as they frame a level one); or for
// LinkSet::Portals one portal with its entry the right one and its exit the
// left one (looking into the entry, one comes out of the exit towards the
// entry again).
frustum::Result<std::vector<ViewLink>> place_facing_links(const frustum::MatrixPair<float>& camera,
                                                          const scene::Bounds& bounds, LinkSet set,
                                                          const std::vector<scene::Bounds>& boxes = {});

// A scene of the links' quads (double-sided; mirrors light grey, portal
// entries violet with a dark frame just behind them, exits orange), whose instances are the links'
// surface_instance / exit_instance / frame_instance (which this sets). The quad of an
// instance is add_quad_instance()'s [-0.5, 0.5]^2; link_world() places it.
scene::Scene link_scene(std::vector<ViewLink>& links);

// The world matrix of a link's quad in link_scene(): the entry's (exit's).
glm::mat4 link_world(const ViewLink& link, bool exit);
// A portal entry's frame in link_scene(): a dark quad 6% of the entry's
// smaller half size wider on each side, a quarter of that behind the entry
// (like the showcase's mirror_backing), so the entry's edge shows whatever
// its view looks like.
glm::mat4 entry_frame_world(const ViewLink& link);

} // namespace plan
