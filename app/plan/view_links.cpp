#include "plan/view_links.hpp"

#include "plan/mirror_placement.hpp"

#include <frustum/lens.hpp>
#include <frustum/portal.hpp>
#include <frustum/queries.hpp>

#include <algorithm>
#include <limits>
#include <string>

namespace plan {
namespace {

constexpr float kMinDepthPerNear = 2.0f; // the anchor lies at least twice the near distance away
constexpr float kInsideDepthFraction = 0.5f; // eye inside the bounds: halfway to where the view axis leaves them
constexpr float kFrameMargin = 0.06f;    // a portal entry's frame: this times its smaller half size wider on each side
constexpr float kFrameDepth = 0.25f;     // and this times that margin behind the entry
// The facing links' corridor along f: from this times d to that times d, or
// to this fraction of the far distance when that is nearer.
constexpr float kCorridorBegin = 0.2f;
constexpr float kCorridorEnd = 6.0f;
constexpr float kCorridorFarFactor = 0.95f;

frustum::Frame<float> frame(const glm::vec3& origin, const glm::vec3& x, const glm::vec3& y) {
    frustum::Frame<float> f;
    f.origin = origin;
    f.x = x;
    f.y = y;
    return f;
}

// How far along the unit direction `d` from `p` (inside `b`) the ray leaves the box.
float exit_distance_m(const glm::vec3& p, const glm::vec3& d, const scene::Bounds& b) {
    float t = std::numeric_limits<float>::infinity();
    for (int i = 0; i < 3; ++i) {
        if (d[i] > 0.0f) {
            t = std::min(t, (b.max[i] - p[i]) / d[i]);
        } else if (d[i] < 0.0f) {
            t = std::min(t, (b.min[i] - p[i]) / d[i]);
        }
    }
    return t;
}

// Where the ray p + t d (t > 0) first meets the box's surface: its entry,
// or its exit when p is inside; empty when it misses.
std::optional<float> box_hit_m(const glm::vec3& p, const glm::vec3& d, const scene::Bounds& b) {
    float t_in = 0.0f, t_out = std::numeric_limits<float>::infinity();
    for (int i = 0; i < 3; ++i) {
        if (d[i] == 0.0f) {
            if (p[i] < b.min[i] || p[i] > b.max[i]) {
                return std::nullopt;
            }
            continue;
        }
        float t0 = (b.min[i] - p[i]) / d[i], t1 = (b.max[i] - p[i]) / d[i];
        if (t0 > t1) {
            std::swap(t0, t1);
        }
        t_in = std::max(t_in, t0);
        t_out = std::min(t_out, t1);
    }
    if (!(t_out >= t_in) || !(t_out > 0.0f)) {
        return std::nullopt;
    }
    return t_in > 0.0f ? t_in : t_out;
}

// The depth along f of what the middle half of the frame sees: the nearest
// hit of kDepthRays x kDepthRays rays through it (u, v in [-1/2, 1/2] of the
// half sizes) against the boxes, each ray's depth at most where it leaves
// the bounds.
constexpr int kDepthRays = 3;
float depth_in_front_m(const frustum::NearPlaneFrame<float>& near, const glm::vec3& forward,
                       const scene::Bounds& bounds, const std::vector<scene::Bounds>& boxes) {
    float nearest_m = std::numeric_limits<float>::infinity();
    for (int j = 0; j < kDepthRays; ++j) {
        for (int i = 0; i < kDepthRays; ++i) {
            const float u = -0.5f + static_cast<float>(i) / (kDepthRays - 1);
            const float v = -0.5f + static_cast<float>(j) / (kDepthRays - 1);
            const glm::vec3 d = glm::normalize(near.center + u * near.half_width_m * near.x_axis +
                                               v * near.half_height_m * near.y_axis - near.eye);
            float t = exit_distance_m(near.eye, d, bounds);
            for (const scene::Bounds& box : boxes) {
                if (const auto hit = box_hit_m(near.eye, d, box)) {
                    t = std::min(t, *hit);
                }
            }
            nearest_m = std::min(nearest_m, t * glm::dot(d, forward));
        }
    }
    return nearest_m;
}

} // namespace

std::vector<scene::Bounds> instance_boxes(const scene::Scene& scene) {
    std::vector<scene::Bounds> boxes;
    for (const scene::Instance& instance : scene.instances) {
        if (instance.mesh < 0 || static_cast<std::size_t>(instance.mesh) >= scene.meshes.size()) {
            continue;
        }
        bool any = false;
        scene::Bounds local;
        for (const scene::Primitive& primitive : scene.meshes[static_cast<std::size_t>(instance.mesh)].primitives) {
            for (const glm::vec3& p : primitive.positions) {
                local.min = any ? glm::min(local.min, p) : p;
                local.max = any ? glm::max(local.max, p) : p;
                any = true;
            }
        }
        if (!any) {
            continue;
        }
        scene::Bounds world{glm::vec3(std::numeric_limits<float>::infinity()),
                            glm::vec3(-std::numeric_limits<float>::infinity())};
        for (const glm::vec3& corner : scene::corners(local)) {
            const glm::vec3 w(instance.world * glm::vec4(corner, 1.0f));
            world.min = glm::min(world.min, w);
            world.max = glm::max(world.max, w);
        }
        boxes.push_back(world);
    }
    return boxes;
}

bool eye_inside(const glm::vec3& eye, const scene::Bounds& bounds) {
    return glm::all(glm::greaterThan(eye, bounds.min)) && glm::all(glm::lessThan(eye, bounds.max));
}

frustum::Result<ViewAnchor> view_anchor(const frustum::MatrixPair<float>& camera, const scene::Bounds& bounds,
                                        const std::vector<scene::Bounds>& boxes, const char* where) {
    auto near = frustum::near_plane_frame(camera);
    if (!near) {
        return frustum::Error{std::string(where) + ": " + near.error()};
    }
    ViewAnchor a;
    a.eye = near->eye;
    a.view_forward = glm::normalize(glm::cross(near->y_axis, near->x_axis));
    a.near_m = glm::dot(near->center - near->eye, a.view_forward);
    const glm::vec3 horizontal = glm::cross(a.view_forward, glm::vec3(0.0f, 1.0f, 0.0f));
    const bool level = glm::length(horizontal) > 1e-3f;
    a.right = level ? glm::normalize(horizontal) : glm::normalize(near->x_axis);
    a.up = level ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::normalize(near->y_axis);
    // Keep the frames orthonormal: forward along the horizontal plane for the quads.
    a.forward = glm::cross(a.up, a.right);
    a.view_up = glm::cross(a.right, a.view_forward);
    a.inside = eye_inside(a.eye, bounds);
    const glm::vec3 center = 0.5f * (bounds.min + bounds.max);
    // Seen from inside (a room, a street), the model's centre may be beside
    // or behind the eye: the depth is then half that of what the middle of
    // the frame sees first (a wall, a table, the houses of the street), so
    // every placed surface stands in the open in front of it.
    const float depth_m = a.inside ? kInsideDepthFraction * depth_in_front_m(*near, a.view_forward, bounds, boxes)
                                   : glm::dot(center - a.eye, a.view_forward);
    a.depth_m = std::max(depth_m, kMinDepthPerNear * a.near_m);
    a.point = a.eye + a.depth_m * a.view_forward;
    a.half_width_m = near->half_width_m * a.depth_m / a.near_m;
    a.half_height_m = near->half_height_m * a.depth_m / a.near_m;
    return a;
}

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
                                                         const scene::Bounds& bounds,
                                                         const std::vector<scene::Bounds>& boxes) {
    auto a = view_anchor(camera, bounds, boxes, "plan::place_portal_pair()");
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
                                                          const scene::Bounds& bounds, LinkSet set,
                                                          const std::vector<scene::Bounds>& boxes) {
    auto a = view_anchor(camera, bounds, boxes, "plan::place_facing_links()");
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
    // Seen from inside, the corridor ends at what the middle of the frame sees first (2 d).
    const float longest_m = (a->inside ? 2.0f : kCorridorEnd) * a->depth_m;
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

} // namespace plan
