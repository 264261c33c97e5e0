// The portal and recursion effects (docs/portals.md) against independent
// references, on a small scene with nothing between the camera and the
// mirrors or the portal: a portal view equals a direct render from the
// virtual camera; recursion level k of two facing mirrors equals the scene
// reflected k times, and level k of a portal facing itself a direct render
// from the camera carried through it k times; nothing behind a mirror or an
// exit portal shows at any level.
#include "render_test_support.hpp"

#include <frustum/projection.hpp>
#include <frustum/reflect.hpp>
#include <frustum/rigid.hpp>
#include <gl/offscreen_target.hpp>
#include <image/compare.hpp>
#include <render/recursion_pass.hpp>
#include <render/scene_pass.hpp>
#include <plan/view_links.hpp>
#include <plan/view_tree.hpp>

namespace {

constexpr int kW = 192, kH = 108;
constexpr glm::vec4 kMarkerColor{1.0f, 0.0f, 0.0f, 1.0f}; // unlit: pure red in the image

void add_box(scene::Scene& s, const glm::vec3& center, float half_m, const glm::vec4& color, bool unlit = false) {
    scene::Material material;
    material.base_color_factor = color;
    material.unlit = unlit;
    s.materials.push_back(material);
    scene::Primitive box;
    for (int i = 0; i < 8; ++i) {
        box.positions.push_back(center + half_m * glm::vec3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1));
    }
    box.indices = {0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4, 2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
    box.material = static_cast<int>(s.materials.size()) - 1;
    s.meshes.push_back(scene::Mesh{"box", {box}});
    scene::Instance instance;
    instance.mesh = static_cast<int>(s.meshes.size()) - 1;
    s.instances.push_back(instance);
}

// Three boxes about the origin; the bounds are theirs (the markers added by
// the tests lie outside them and do not move the links).
scene::Scene small_scene() {
    scene::Scene s;
    add_box(s, {0.0f, 0.0f, 0.0f}, 0.3f, {0.2f, 0.5f, 0.9f, 1.0f});
    add_box(s, {0.5f, -0.2f, -0.8f}, 0.2f, {0.2f, 0.8f, 0.3f, 1.0f});
    add_box(s, {-0.6f, 0.25f, -1.2f}, 0.25f, {0.95f, 0.7f, 0.1f, 1.0f});
    s.world_bounds = {{-0.85f, -0.4f, -1.45f}, {0.7f, 0.55f, 0.3f}};
    return s;
}

// From (0.3, 0.4, 4) looking down -z, 45 degrees, far 200 m: nothing of
// the corridor the links make is beyond the far plane, so the tilted far
// plane of an oblique frustum (eq. 20-22) clips nothing either.
frustum::MatrixPair<float> test_camera() {
    auto projection = frustum::perspective<float>(glm::radians(45.0f), float(kW) / float(kH), 0.1f, 200.0f,
                                                  frustum::DepthRange::ZeroToOne);
    REQUIRE(projection.ok());
    const auto view = frustum::RigidTransform<float>::from_rotation_translation(glm::mat3(1.0f),
                                                                                -glm::vec3(0.3f, 0.4f, 4.0f));
    return frustum::compose(*projection, view);
}

struct Setup {
    std::unique_ptr<render_test::RenderEnvironment> r;
    plan::Cameras cameras;
    std::optional<render::DepthPolicy> depth;
};

std::optional<Setup> make_setup(const scene::Scene& s) {
    auto r = render_test::make_any_renderer(s);
    if (!r) {
        return std::nullopt;
    }
    auto cameras = plan::make_cameras(s, -1, kW, kH);
    REQUIRE_MESSAGE(cameras.ok(), cameras.error());
    cameras->main.pair = test_camera();
    auto depth = render::DepthPolicy::apply(r->env->fn, *r->env->context, render::DepthPath::ClipControlWhenAvailable);
    REQUIRE_MESSAGE(depth.ok(), depth.error());
    return Setup{std::move(r), std::move(*cameras), std::move(*depth)};
}

image::Image read(const gl::OffscreenTarget& target) {
    auto picture = target.read_rgba8();
    REQUIRE_MESSAGE(picture.ok(), picture.error());
    return std::move(*picture);
}

// The recursion frame through `links` at `depth`, tint 1; the views' targets from `pool` when given.
image::Image recursion_frame(const Setup& s, const std::vector<plan::ViewLink>& links, const render::GpuScene& quads,
                             const std::vector<plan::ViewNode>& nodes, render::TargetPool* pool = nullptr) {
    const gl::Functions& fn = s.r->env->fn;
    auto frame = gl::OffscreenTarget::create(fn, {kW, kH});
    REQUIRE_MESSAGE(frame.ok(), frame.error());
    const render::PassContext ctx = s.r->renderer->pass_context(*s.depth, render::Lighting{});
    const auto status =
        render::draw_recursion_frame(ctx, *frame, render::RecursionDraw{nodes, links, quads, glm::vec3(1.0f), pool});
    REQUIRE_MESSAGE(status.ok(), status.error());
    return read(*frame);
}

// Pixels whose centre lies inside every polygon (projected with `camera`)
// by at least `margin_px`: the region a chain of links covers on screen.
render_test::Mask polygon_mask(const frustum::MatrixPair<float>& camera,
                               const std::vector<std::vector<glm::vec3>>& polygons, float margin_px) {
    std::vector<std::vector<glm::vec2>> screen;
    for (const auto& polygon : polygons) {
        std::vector<glm::vec2> p;
        for (const glm::vec3& corner : polygon) {
            const glm::vec4 clip = camera.matrix() * glm::vec4(corner, 1.0f);
            REQUIRE(clip.w > 0.0f);
            p.emplace_back((clip.x / clip.w * 0.5f + 0.5f) * kW, (clip.y / clip.w * 0.5f + 0.5f) * kH);
        }
        screen.push_back(p);
    }
    render_test::Mask mask(static_cast<std::size_t>(kW * kH), false);
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            const glm::vec2 c(x + 0.5f, (kH - 1 - y) + 0.5f); // image rows are top to bottom
            bool inside = true;
            for (const auto& p : screen) {
                // Signed distances to the edges, one orientation for all (convex).
                float lowest = 1e9f, highest = -1e9f;
                for (std::size_t i = 0; i < p.size(); ++i) {
                    const glm::vec2 a = p[i], b = p[(i + 1) % p.size()];
                    const glm::vec2 e = b - a;
                    const float d = (e.x * (c.y - a.y) - e.y * (c.x - a.x)) / glm::length(e);
                    lowest = std::min(lowest, d);
                    highest = std::max(highest, d);
                }
                inside = inside && (lowest >= margin_px || highest <= -margin_px);
            }
            mask[static_cast<std::size_t>(y * kW + x)] = inside;
        }
    }
    return mask;
}

// Draws the scene and the link quads (less `skip`) with camera and model
// transform into a full-size target.
image::Image direct(const Setup& s, const render::GpuScene& quads, const frustum::MatrixPair<float>& camera,
                    const glm::mat4& pre_model, std::optional<frustum::Plane<float>> clip, int skip,
                    bool with_quads = true) {
    const gl::Functions& fn = s.r->env->fn;
    auto target = gl::OffscreenTarget::create(fn, {kW, kH});
    REQUIRE_MESSAGE(target.ok(), target.error());
    const render::PassContext ctx = s.r->renderer->pass_context(*s.depth, render::Lighting{});
    const render::PassContext link_ctx{ctx.fn, ctx.api, ctx.programs, quads, ctx.depth, ctx.lighting};
    render::begin_frame(ctx);
    render::SceneDraw draw(camera);
    draw.pre_model = pre_model;
    draw.clip_plane = clip;
    render::draw_scene(ctx, draw);
    draw.skip_instance = skip;
    if (with_quads) {
        render::draw_scene(link_ctx, draw);
    }
    return read(*target);
}

int count_color(const image::Image& picture, const render_test::Mask* mask, const glm::vec4& color) {
    int n = 0;
    for (int y = 0; y < picture.height; ++y) {
        for (int x = 0; x < picture.width; ++x) {
            const image::Rgba p = image::pixel_at(picture, x, y);
            const bool in = !mask || (*mask)[static_cast<std::size_t>(y * picture.width + x)];
            n += in && std::abs(p[0] - 255 * color.r) <= 8 && std::abs(p[1] - 255 * color.g) <= 8 &&
                 std::abs(p[2] - 255 * color.b) <= 8;
        }
    }
    return n;
}

void check_same(const image::Image& a, const image::Image& b, const render_test::Mask& mask, const std::string& what,
                int min_pixels) {
    const auto d = render_test::compare_masked(a, b, mask, 2);
    MESSAGE(what << ": " << d.compared << " pixels, " << d.pixels_over << " over 2 LSB, max " << d.max_abs);
    CHECK(d.compared >= min_pixels);
    CHECK(d.pixels_over <= d.compared / 100);
    if (d.pixels_over > d.compared / 100) {
        render_test::save_failure(what, a, b);
    }
}

// F of a frame (local to world: columns x, y, n, origin) and F^-1 = [F_R^T | -F_R^T origin], by hand.
glm::mat4 frame_matrix(const frustum::Frame<float>& f) {
    return glm::mat4(glm::vec4(f.x, 0.0f), glm::vec4(f.y, 0.0f), glm::vec4(f.normal(), 0.0f), glm::vec4(f.origin, 1.0f));
}
glm::mat4 frame_inverse(const frustum::Frame<float>& f) {
    const glm::mat3 rt = glm::transpose(glm::mat3(f.x, f.y, f.normal()));
    glm::mat4 out(rt);
    out[3] = glm::vec4(-(rt * f.origin), 1.0f);
    return out;
}

// What a link does to the scene a view through it draws, and its inverse,
// built here from the link's frames (not with the library's mirror() or
// portal()): a mirror's reflection (its own inverse, eq. 16); a portal's
// P = F_entry H F_exit^-1 with H the half turn diag(-1, 1, -1) about y
// (P^-1 = F_exit H F_entry^-1). The view through the link is the camera
// composed with it.
frustum::RigidTransform<float> carry_of(const plan::ViewLink& link) {
    frustum::RigidTransform<float> carry;
    if (link.kind == plan::ViewLink::Kind::Mirror) {
        carry.matrix = carry.inverse = frustum::reflection_matrix(link.near_plane());
        return carry;
    }
    const glm::mat4 half_turn(glm::vec4(-1, 0, 0, 0), glm::vec4(0, 1, 0, 0), glm::vec4(0, 0, -1, 0), glm::vec4(0, 0, 0, 1));
    carry.matrix = frame_matrix(link.entry) * half_turn * frame_inverse(link.exit);
    carry.inverse = frame_matrix(link.exit) * half_turn * frame_inverse(link.entry);
    return carry;
}

// For k = 1..max_depth: the recursion frame at depth k, inside the region
// of each level-k leaf (the link quads' images along its chain, 1.5 px in
// from their edges, less what the levels before show in front of their
// link), equals a direct render of the scene carried by the chain's links
// (camera * C_1 ... C_k), clipped by the last link's near plane carried
// the same way. Tolerance: 2 LSB, up to 1% of the pixels over (edges).
// Not trivial: over 1/8 of those pixels differ from the plain camera's
// view and from level k - 1's (measured: 27% and more, see the MESSAGEs).
void check_levels(plan::LinkSet set, int max_depth) {
    CAPTURE(plan::to_string(set));
    scene::Scene s = small_scene();
    auto setup = make_setup(s);
    if (!setup) {
        return;
    }
    const auto& camera = setup->cameras.main.pair;
    auto links = plan::place_facing_links(camera, s.world_bounds, set);
    REQUIRE_MESSAGE(links.ok(), links.error());
    auto quads = render::GpuScene::upload(setup->r->env->fn, plan::link_scene(*links));
    REQUIRE_MESSAGE(quads.ok(), quads.error());
    const image::Image plain = direct(*setup, *quads, camera, glm::mat4(1.0f), std::nullopt, -1);
    for (int k = 1; k <= max_depth; ++k) {
        auto nodes = plan::plan_view_tree(camera, *links, {k, kW, kH, plan::ViewBounds::Tight});
        REQUIRE_MESSAGE(nodes.ok(), nodes.error());
        const image::Image frame = recursion_frame(*setup, *links, *quads, *nodes);
        int leaves = 0;
        for (std::size_t leaf = 0; leaf < nodes->size(); ++leaf) {
            if ((*nodes)[leaf].level != k) {
                continue;
            }
            ++leaves;
            // The chain camera -> leaf: W = C_1 ... C_k, and the regions of the links' images.
            std::vector<int> chain;
            for (int n = static_cast<int>(leaf); n > 0; n = (*nodes)[static_cast<std::size_t>(n)].parent) {
                chain.insert(chain.begin(), n);
            }
            frustum::RigidTransform<float> world; // W and W^-1 = C_k^-1 ... C_1^-1
            std::vector<std::vector<glm::vec3>> regions;
            frustum::Plane<float> last{0.0f, 0.0f, 1.0f, 0.0f};
            // What the levels before k show of the scene (no quads): where
            // any of it is not sky, an object stands in front of the level's
            // link and hides level k; those pixels are not compared.
            std::vector<image::Image> in_front;
            std::optional<frustum::Plane<float>> in_front_clip;
            for (int n : chain) {
                in_front.push_back(direct(*setup, *quads, camera, world.matrix,
                                          in_front_clip ? std::optional(frustum::transformed(*in_front_clip, world))
                                                        : std::nullopt,
                                          -1, false));
                const plan::ViewLink& link = (*links)[static_cast<std::size_t>((*nodes)[static_cast<std::size_t>(n)].link)];
                std::vector<glm::vec3> image_quad;
                for (const glm::vec3& corner : link.quad()) {
                    image_quad.emplace_back(world.matrix * glm::vec4(corner, 1.0f));
                }
                regions.push_back(image_quad);
                last = link.near_plane();
                in_front_clip = last;
                const frustum::RigidTransform<float> c = carry_of(link);
                world.matrix = world.matrix * c.matrix;
                world.inverse = c.inverse * world.inverse;
            }
            // Keep what lies in front of the last link's near plane, carried by W.
            const frustum::Plane<float> clip = frustum::transformed(last, world);
            const plan::ViewLink& through = (*links)[static_cast<std::size_t>((*nodes)[leaf].link)];
            const int on_near_plane = through.kind == plan::ViewLink::Kind::Mirror ? through.surface_instance
                                                                                     : through.exit_instance;
            const image::Image reference = direct(*setup, *quads, camera, world.matrix, clip, on_near_plane);
            auto mask = polygon_mask(camera, regions, 1.5f);
            const image::Rgba sky = image::pixel_at(in_front.front(), 0, 0); // a sky pixel (top left)
            for (const image::Image& picture : in_front) {
                for (int y = 0; y < kH; ++y) {
                    for (int x = 0; x < kW; ++x) {
                        const image::Rgba p = image::pixel_at(picture, x, y);
                        if (p[0] != sky[0] || p[1] != sky[1] || p[2] != sky[2]) {
                            mask[static_cast<std::size_t>(y * kW + x)] = false;
                        }
                    }
                }
            }
            check_same(frame, reference, mask,
                       "recursion-" + std::string(plan::to_string(set)) + "-level-" + std::to_string(k) + "-node-" +
                           std::to_string(leaf),
                       k == 1 ? 300 : 20);
            // Not trivial: there the frame differs from the plain camera's
            // (which shows the link's own colour) and from level k - 1's view.
            const frustum::RigidTransform<float> back = carry_of(through);
            const image::Image shallower =
                direct(*setup, *quads, camera, world.matrix * back.inverse, std::nullopt, on_near_plane);
            const int compared = render_test::count(mask);
            const int unlike_plain = render_test::compare_masked(frame, plain, mask, 2).pixels_over;
            const int unlike_shallower = render_test::compare_masked(frame, shallower, mask, 2).pixels_over;
            MESSAGE("level " << k << ": " << unlike_plain << " and " << unlike_shallower << " of " << compared
                             << " pixels differ from the plain view and from level k - 1's");
            CHECK(unlike_plain > compared / 8);
            CHECK(unlike_shallower > compared / 8);
        }
        CHECK(leaves >= 1); // the recursion reached level k
    }
}

} // namespace

TEST_SUITE("gl") {

TEST_CASE("a portal view equals a direct render from the camera carried through the portal by hand") {
    scene::Scene s = small_scene();
    auto setup = make_setup(s);
    if (!setup) {
        return;
    }
    auto links = plan::place_portal_pair(setup->cameras.main.pair, s.world_bounds);
    REQUIRE_MESSAGE(links.ok(), links.error());
    auto quads = render::GpuScene::upload(setup->r->env->fn, plan::link_scene(*links));
    REQUIRE_MESSAGE(quads.ok(), quads.error());
    auto nodes = plan::plan_view_tree(setup->cameras.main.pair, *links, {1, kW, kH, plan::ViewBounds::Tight});
    REQUIRE_MESSAGE(nodes.ok(), nodes.error());
    REQUIRE(nodes->size() == 2); // the camera and the view through the entry
    const image::Image frame = recursion_frame(*setup, *links, *quads, *nodes);
    // The virtual camera built here from the two frames, not plan_view_tree's:
    // the camera composed with P = F_entry H F_exit^-1 (carry_of), over the
    // whole image, keeping what lies in front of the exit (its near plane
    // carried by P), the exit quad (on that plane) left out.
    const plan::ViewLink& portal = links->front();
    const frustum::RigidTransform<float> carry = carry_of(portal);
    const image::Image reference =
        direct(*setup, *quads, setup->cameras.main.pair, carry.matrix,
               frustum::transformed(portal.near_plane(), carry), portal.exit_instance);
    const auto mask = polygon_mask(setup->cameras.main.pair, {links->front().quad()}, 1.0f);
    // The texture's texels are the screen's pixels (crop is exact): 2 LSB,
    // up to 1% over (edges). Measured: 1260 pixels, 0 over 2 LSB, max 0.
    check_same(frame, reference, mask, "portal", 300);
    // Not trivial: the portal shows other pixels than the plain camera does there.
    const image::Image plain = direct(*setup, *quads, setup->cameras.main.pair, glm::mat4(1.0f), std::nullopt, -1);
    CHECK(render_test::compare_masked(frame, plain, mask, 2).pixels_over > render_test::count(mask) / 4);
}

TEST_CASE("recursion level k of two facing mirrors equals the scene reflected k times") {
    check_levels(plan::LinkSet::Mirrors, 3);
}

TEST_CASE("recursion level k of a portal facing itself equals a direct render from the k-times-portalled camera") {
    check_levels(plan::LinkSet::Portals, 3);
}

// render::TargetPool (the renderer's, kept across frames): the same
// pixels as targets made per view; the second frame of the same views makes
// no target; a frame that takes none frees them all.
TEST_CASE("kept view targets: the same pixels, none made for a second frame of the same views") {
    scene::Scene s = small_scene();
    auto setup = make_setup(s);
    if (!setup) {
        return;
    }
    auto links = plan::place_facing_links(setup->cameras.main.pair, s.world_bounds, plan::LinkSet::Mirrors);
    REQUIRE_MESSAGE(links.ok(), links.error());
    auto quads = render::GpuScene::upload(setup->r->env->fn, plan::link_scene(*links));
    REQUIRE_MESSAGE(quads.ok(), quads.error());
    auto nodes = plan::plan_view_tree(setup->cameras.main.pair, *links, {3, kW, kH, plan::ViewBounds::Tight});
    REQUIRE_MESSAGE(nodes.ok(), nodes.error());
    REQUIRE(nodes->size() > 2);
    const image::Image made_per_view = recursion_frame(*setup, *links, *quads, *nodes);
    render::TargetPool pool;
    const image::Image first = recursion_frame(*setup, *links, *quads, *nodes, &pool);
    const std::size_t made = pool.made();
    MESSAGE((nodes->size() - 1) << " views, " << made << " targets made");
    CHECK(made >= 1);
    CHECK(made <= nodes->size() - 1);
    CHECK(pool.free_count() == made);
    const image::Image second = recursion_frame(*setup, *links, *quads, *nodes, &pool);
    CHECK(pool.made() == made);
    for (const image::Image* frame : {&first, &second}) {
        const auto diff = image::compare(*frame, made_per_view, 0);
        REQUIRE_MESSAGE(diff.ok(), diff.error());
        CHECK(diff->pixels_over == 0);
    }
    auto camera_only = plan::plan_view_tree(setup->cameras.main.pair, *links, {0, kW, kH, plan::ViewBounds::Tight});
    REQUIRE_MESSAGE(camera_only.ok(), camera_only.error());
    recursion_frame(*setup, *links, *quads, *camera_only, &pool);
    CHECK(pool.free_count() == 0);
}

TEST_CASE("nothing behind a mirror or an exit portal appears at any level") {
    for (plan::LinkSet set : {plan::LinkSet::Mirrors, plan::LinkSet::Portals}) {
        CAPTURE(plan::to_string(set));
        scene::Scene s = small_scene();
        auto probe = make_setup(s);
        if (!probe) {
            return;
        }
        auto links = plan::place_facing_links(probe->cameras.main.pair, s.world_bounds, set);
        REQUIRE_MESSAGE(links.ok(), links.error());
        // A red marker just behind the left link (a mirror, or the portal's exit), within its quad.
        const plan::ViewLink& left = links->front(); // mirrors: the left one; portals: the only one
        const frustum::Frame<float>& behind = set == plan::LinkSet::Mirrors ? left.entry : left.exit;
        // At the depth of the model's centre, 0.3 m behind the link's plane.
        const glm::vec3 center = 0.5f * (s.world_bounds.min + s.world_bounds.max);
        add_box(s, behind.origin + glm::dot(center - behind.origin, behind.x) * behind.x - 0.3f * behind.normal(),
                0.2f, kMarkerColor, true);
        auto setup = make_setup(s);
        REQUIRE(setup);
        auto quads = render::GpuScene::upload(setup->r->env->fn, plan::link_scene(*links));
        REQUIRE_MESSAGE(quads.ok(), quads.error());
        for (int depth : {1, 4}) {
            auto nodes = plan::plan_view_tree(setup->cameras.main.pair, *links, {depth, kW, kH, plan::ViewBounds::Tight});
            REQUIRE_MESSAGE(nodes.ok(), nodes.error());
            int deepest = 0;
            for (const plan::ViewNode& node : *nodes) {
                deepest = std::max(deepest, node.level);
            }
            CHECK(deepest == depth); // the recursion got as deep as asked
            CHECK(count_color(recursion_frame(*setup, *links, *quads, *nodes), nullptr, kMarkerColor) == 0);
            // The same views without their near planes (reflect / carry only) do show it: the check can fail.
            auto bare = plan::plan_view_tree(setup->cameras.main.pair, *links, {depth, kW, kH, plan::ViewBounds::FullViewport});
            REQUIRE_MESSAGE(bare.ok(), bare.error());
            for (plan::ViewNode& node : *bare) {
                node.clip_plane.reset();
            }
            CHECK(count_color(recursion_frame(*setup, *links, *quads, *bare), nullptr, kMarkerColor) > 10);
        }
    }
}

TEST_CASE("plan_view_tree: depth 0 is the camera alone, and the depth is checked") {
    const scene::Scene s = small_scene();
    const frustum::MatrixPair<float> camera = test_camera();
    auto links = plan::place_facing_links(camera, s.world_bounds, plan::LinkSet::Mirrors);
    REQUIRE(links.ok());
    auto none = plan::plan_view_tree(camera, *links, {0, kW, kH, plan::ViewBounds::Tight});
    REQUIRE(none.ok());
    CHECK(none->size() == 1);
    auto bad = plan::plan_view_tree(camera, *links, {9, kW, kH, plan::ViewBounds::Tight});
    REQUIRE_FALSE(bad.ok());
    CHECK(bad.error() == "plan::plan_view_tree(): depth 9 must be in 0..8");
    // Each level's rectangle lies inside its parent's.
    auto tree = plan::plan_view_tree(camera, *links, {6, kW, kH, plan::ViewBounds::Tight});
    REQUIRE(tree.ok());
    for (const plan::ViewNode& node : *tree) {
        if (node.parent < 0) {
            continue;
        }
        const auto& p = (*tree)[static_cast<std::size_t>(node.parent)].rect;
        CHECK(node.rect.x >= p.x);
        CHECK(node.rect.y >= p.y);
        CHECK(node.rect.x + node.rect.width <= p.x + p.width);
        CHECK(node.rect.y + node.rect.height <= p.y + p.height);
    }
}

} // TEST_SUITE
