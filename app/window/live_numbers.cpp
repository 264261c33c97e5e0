#include "window/live_numbers.hpp"

#include <plan/link_moves.hpp>
#include <plan/view_links.hpp>
#include <plan/view_tree.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace window {
namespace {

template <class F>
double microseconds(F&& work) {
    const auto start = std::chrono::steady_clock::now();
    work();
    return std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
}

} // namespace

double inverse_residual(const frustum::MatrixPair<float>& pair) {
    const glm::dmat4 product = glm::dmat4(pair.matrix()) * glm::dmat4(pair.inverse());
    double worst = 0.0;
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            worst = std::max(worst, std::abs(product[c][r] - (c == r ? 1.0 : 0.0)));
        }
    }
    return worst;
}

LiveNumbers live_numbers(const Frame& frame, const scene::Scene& scene) {
    // The camera the frame's effect draws with (an orthographic main's
    // perspective twin for the effects built from an eye).
    const plan::Cameras cameras = plan::cameras_for(frame.effect, frame.cameras);
    LiveNumbers numbers{cameras.main.pair, 0.0, {}, {}, std::nullopt, {}};
    const frustum::MatrixPair<float>& camera = cameras.main.pair;
    numbers.residual = inverse_residual(camera);
    numbers.planes = frustum::planes(camera);
    numbers.points = frustum::key_points(camera);
    const float tolerance = frustum::infinity_tolerance<float>();
    for (glm::vec4& corner : numbers.points.corners) {
        corner = frustum::to_point(corner, tolerance);
    }
    for (glm::vec4* point : {&numbers.points.center, &numbers.points.eye, &numbers.points.vanishing_x,
                             &numbers.points.vanishing_y}) {
        *point = frustum::to_point(*point, tolerance);
    }
    const int width_px = frame.options.width_px, height_px = frame.options.height_px;
    const bool mirror_pass = frame.effect == plan::Effect::Mirror || frame.effect == plan::Effect::Curved ||
                             frame.effect == plan::Effect::Frustum; // the effects that plan the reflection
    if (scene.mirror) {
        numbers.mirror_rect = plan::mirror_screen_rect(*scene.mirror, camera, width_px, height_px);
    }
    if (scene.mirror && mirror_pass) {
        PassTiming timing{"mirror pair (" + std::string(plan::to_string(frame.options.mirror_method)) + ")", 0.0, ""};
        frustum::Result<std::optional<plan::ReflectionView>> view = frustum::Error{""};
        timing.cpu_us = microseconds([&] {
            view = plan::plan_reflection(*scene.mirror, camera, width_px, height_px, frame.options.mirror_method,
                                         scene.world_bounds);
        });
        timing.result = !view ? view.error()
                        : *view ? std::to_string((*view)->texture_width_px) + "x" +
                                      std::to_string((*view)->texture_height_px) + " px texture"
                                : "mirror not seen";
        numbers.passes.push_back(std::move(timing));
    }
    if (frame.effect == plan::Effect::Recursion) {
        PassTiming timing{"recursion views (depth " + std::to_string(frame.options.recursion_depth) + ")", 0.0, ""};
        frustum::Result<std::vector<plan::ViewNode>> nodes = frustum::Error{""};
        timing.cpu_us = microseconds([&] {
            auto links = plan::place_facing_links(camera, scene.world_bounds, frame.options.recursion_links,
                                                  plan::instance_boxes(scene));
            if (!links) {
                nodes = links.take_error();
                return;
            }
            plan::move_links(*links, frame.options.link_moves);
            nodes = plan::plan_view_tree(camera, *links,
                                         {frame.options.recursion_depth, width_px, height_px,
                                          plan::ViewBounds::Tight});
        });
        timing.result = nodes ? std::to_string(nodes->size()) + " views" : nodes.error();
        numbers.passes.push_back(std::move(timing));
    }
    return numbers;
}

} // namespace window
