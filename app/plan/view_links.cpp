#include "plan/view_links.hpp"

#include "plan/mirror_placement.hpp"

#include <frustum/lens.hpp>
#include <frustum/portal.hpp>
#include <frustum/queries.hpp>

#include <algorithm>
#include <string>

namespace render {
namespace {

constexpr float kMinDepthPerNear = 2.0f; // the anchor lies at least twice the near distance away
constexpr float kFrameMargin = 0.06f;    // a portal entry's frame: this times its smaller half size wider on each side
constexpr float kFrameDepth = 0.25f;     // and this times that margin behind the entry
// The facing links' corridor along f: from this times d to that times d, or
// to this fraction of the far distance when that is nearer.
constexpr float kCorridorBegin = 0.2f;
constexpr float kCorridorEnd = 6.0f;
constexpr float kCorridorFarFactor = 0.95f;

// E, f, R, U, the anchor A and the frame's half sizes there (view_links.hpp).
struct Anchor {
    glm::vec3 eye, forward, right, up, point;
    glm::vec3 view_forward, view_up; // f itself and R x f: the view's own frame (up tilted with the camera's pitch)
    float depth_m, half_width_m, half_height_m;
};

frustum::Result<Anchor> anchor_of(const frustum::MatrixPair<float>& camera, const scene::Bounds& bounds,
                                  const char* where) {
    auto near = frustum::near_plane_frame(camera);
    if (!near) {
        return frustum::Error{std::string(where) + ": " + near.error()};
    }
    Anchor a;
    a.eye = near->eye;
    a.view_forward = glm::normalize(glm::cross(near->y_axis, near->x_axis));
    const float near_m = glm::dot(near->center - near->eye, a.view_forward);
    const glm::vec3 horizontal = glm::cross(a.view_forward, glm::vec3(0.0f, 1.0f, 0.0f));
    const bool level = glm::length(horizontal) > 1e-3f;
    a.right = level ? glm::normalize(horizontal) : glm::normalize(near->x_axis);
    a.up = level ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::normalize(near->y_axis);
    // Keep the frames orthonormal: forward along the horizontal plane for the quads.
    a.forward = glm::cross(a.up, a.right);
    a.view_up = glm::cross(a.right, a.view_forward);
    const glm::vec3 center = 0.5f * (bounds.min + bounds.max);
    a.depth_m = std::max(glm::dot(center - a.eye, a.view_forward), kMinDepthPerNear * near_m);
    a.point = a.eye + a.depth_m * a.view_forward;
    a.half_width_m = near->half_width_m * a.depth_m / near_m;
    a.half_height_m = near->half_height_m * a.depth_m / near_m;
    return a;
}

frustum::Frame<float> frame(const glm::vec3& origin, const glm::vec3& x, const glm::vec3& y) {
    frustum::Frame<float> f;
    f.origin = origin;
    f.x = x;
    f.y = y;
    return f;
}

} // namespace

glm::mat4 link_world(const ViewLink& link, bool exit) {
    const frustum::Frame<float>& f = exit ? link.exit : link.entry;
    // add_quad_instance()'s quad is [-0.5, 0.5]^2: scale by the full size.
    return glm::mat4(glm::vec4(2.0f * link.half_width_m * f.x, 0.0f), glm::vec4(2.0f * link.half_height_m * f.y, 0.0f),
                     glm::vec4(f.normal(), 0.0f), glm::vec4(f.origin, 1.0f));
}

glm::mat4 entry_frame_world(const ViewLink& link) {
    const float rim_m = kFrameMargin * std::min(link.half_width_m, link.half_height_m);
    ViewLink rim = link;
    rim.half_width_m += rim_m;
    rim.half_height_m += rim_m;
    rim.entry.origin -= kFrameDepth * rim_m * link.entry.normal();
    return link_world(rim, false);
}

std::vector<glm::vec3> ViewLink::quad() const {
    const glm::vec3 u = half_width_m * entry.x, v = half_height_m * entry.y;
    return {entry.origin - u - v, entry.origin + u - v, entry.origin + u + v, entry.origin - u + v};
}

frustum::Plane<float> ViewLink::near_plane() const {
    return frustum::frame_plane(kind == Kind::Mirror ? entry : exit);
}

std::string_view to_string(LinkSet set) { return set == LinkSet::Mirrors ? "mirrors" : "portals"; }

std::optional<LinkSet> parse_link_set(std::string_view text) {
    for (LinkSet set : {LinkSet::Mirrors, LinkSet::Portals}) {
        if (text == to_string(set)) {
            return set;
        }
    }
    return std::nullopt;
}

frustum::Result<std::vector<ViewLink>> place_portal_pair(const frustum::MatrixPair<float>& camera,
                                                         const scene::Bounds& bounds) {
    auto a = anchor_of(camera, bounds, "render::place_portal_pair()");
    if (!a) {
        return frustum::Error{a.error()};
    }
    ViewLink link;
    link.kind = ViewLink::Kind::Portal;
    link.half_height_m = 0.4f * a->half_height_m;
    link.half_width_m = 0.3f * a->half_height_m;
    // Entry: x = R, y = U, normal R x U = -f (towards the camera). Exit: x = f, normal f x U = R.
    link.entry = frame(a->point + 0.5f * a->half_width_m * a->right, a->right, a->up);
    link.exit = frame(a->point - 0.6f * a->half_width_m * a->right, a->forward, a->up);
    return std::vector<ViewLink>{link};
}

frustum::Result<std::vector<ViewLink>> place_facing_links(const frustum::MatrixPair<float>& camera,
                                                          const scene::Bounds& bounds, LinkSet set) {
    auto a = anchor_of(camera, bounds, "render::place_facing_links()");
    if (!a) {
        return frustum::Error{a.error()};
    }
    const float reach_m = 0.45f * a->half_width_m;
    // From depth 0.2 d to 6 d along f: a corridor long enough for rays to
    // bounce about six times within the frame's horizontal field; it ends
    // 5% short of a nearer far plane (each reflection keeps the depths
    // along f, so every view of the corridor keeps some of it in view).
    const auto far_m = frustum::far_distance(camera);
    const float begin_m = kCorridorBegin * a->depth_m;
    const float longest_m = kCorridorEnd * a->depth_m;
    const float end_m = std::max(far_m ? std::min(longest_m, kCorridorFarFactor * *far_m) : longest_m, 2.0f * begin_m);
    // The quads lie along f and R x f, not along the horizontal: seen from
    // a camera looking down on the model they cover the view's sides as
    // from a level one (their planes stay vertical: normals +-R).
    const glm::vec3 middle = a->eye + 0.5f * (begin_m + end_m) * a->view_forward;
    // Left faces +R (x = f), right faces -R (x = -f).
    const auto left = frame(middle - reach_m * a->right, a->view_forward, a->view_up);
    const auto right = frame(middle + reach_m * a->right, -a->view_forward, a->view_up);
    ViewLink l, r;
    l.half_width_m = r.half_width_m = 0.5f * (end_m - begin_m);
    l.half_height_m = r.half_height_m = 0.6f * a->half_height_m;
    if (set == LinkSet::Portals) {
        r.kind = ViewLink::Kind::Portal;
        r.entry = right;
        r.exit = left;
        return std::vector<ViewLink>{r};
    }
    l.entry = left;
    r.entry = right;
    return std::vector<ViewLink>{l, r};
}

scene::Scene link_scene(std::vector<ViewLink>& links) {
    scene::Scene scene;
    for (ViewLink& link : links) {
        const bool mirror = link.kind == ViewLink::Kind::Mirror;
        link.surface_instance = add_quad_instance(scene, link_world(link, false),
                                         mirror ? glm::vec4(0.8f, 0.8f, 0.82f, 1.0f)
                                                : glm::vec4(0.55f, 0.35f, 0.85f, 1.0f),
                                         mirror ? "mirror (link)" : "portal entry");
        if (!mirror) {
            link.exit_instance = add_quad_instance(scene, link_world(link, true),
                                          glm::vec4(0.95f, 0.55f, 0.2f, 1.0f), "portal exit");
            link.frame_instance = add_quad_instance(scene, entry_frame_world(link), glm::vec4(0.12f, 0.1f, 0.16f, 1.0f),
                                                    "portal entry frame");
        }
    }
    return scene;
}

} // namespace render
