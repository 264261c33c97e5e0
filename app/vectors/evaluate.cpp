#include "vectors/evaluate.hpp"

#include "vectors/camera.hpp"

#include <frustum/crop.hpp>
#include <frustum/detail/errors.hpp>
#include <frustum/culling.hpp>
#include <frustum/jitter.hpp>
#include <frustum/portal.hpp>
#include <frustum/screen_rect.hpp>
#include <frustum/mirror.hpp>
#include <frustum/oblique_clip.hpp>
#include <frustum/projection.hpp>
#include <frustum/queries.hpp>
#include <frustum/reflect.hpp>
#include <frustum/validate.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>
#include <utility>

namespace vectors {

namespace {

using Pair = frustum::MatrixPair<double>;
using PairResult = frustum::Result<Pair>;

PairResult apply_op(const Pair& pair, const Op& op) {
    if (const auto* crop = std::get_if<CropOp>(&op)) {
        const frustum::CropRect<double> rect{crop->x,     crop->y,          crop->width,
                                             crop->height, crop->full_width, crop->full_height};
        return frustum::crop(pair, rect); // §5.1
    }
    if (const auto* j = std::get_if<JitterOp>(&op)) {
        return frustum::jitter(pair, j->dx, j->dy, j->full_width, j->full_height);
    }
    if (const auto* portal = std::get_if<PortalOp>(&op)) {
        const auto frame = [](const FrameSpec& f) { return frustum::Frame<double>{f.origin, f.x, f.y}; };
        return frustum::portal(pair, frame(portal->entry), frame(portal->exit));
    }
    const auto& plane_op = std::get<PlaneOp>(op);
    const frustum::Plane<double> plane(plane_op.plane);
    switch (plane_op.kind) {
    case PlaneOp::Kind::Reflect: return frustum::reflect(pair, plane);    // §5.2, first step
    case PlaneOp::Kind::Clip: return frustum::clip_oblique(pair, plane); // §5.2, second step
    case PlaneOp::Kind::Mirror: return frustum::mirror(pair, plane);     // both, same plane
    }
    return frustum::Error{"unknown op"};
}

const char* op_key(const Op& op) {
    if (std::holds_alternative<CropOp>(op)) {
        return "crop";
    }
    if (std::holds_alternative<JitterOp>(op)) {
        return "jitter";
    }
    if (std::holds_alternative<PortalOp>(op)) {
        return "portal";
    }
    return op_name(std::get<PlaneOp>(op).kind);
}

bool finite(const Vec4& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

bool finite(const Mat4& m) { return finite(m[0]) && finite(m[1]) && finite(m[2]) && finite(m[3]); }

// Normalizes a raw plane without overflow (glm::length squares, so a
// normal of 1e200 would become infinite); a zero or non-finite normal (a
// plane at infinity) is an error, never a division by zero.
frustum::Result<Vec4> unit_plane(const frustum::Plane<double>& raw, const char* name) {
    const Vec4& p = raw.abcd;
    const double largest = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    if (!finite(p) || !(largest > 0.0)) {
        return frustum::Error{std::string("planes: the ") + name +
                              " plane has a zero or non-finite normal (a plane at infinity)"};
    }
    const Vec4 scaled = p / largest;
    const Vec4 unit = scaled / glm::length(Vec3(scaled));
    if (!finite(unit)) {
        return frustum::Error{std::string("planes: the ") + name + " plane is not representable in double"};
    }
    return unit;
}

frustum::Result<UnitPlanes> unit_planes(const Pair& pair) {
    const frustum::FrustumPlanes<double> raw = frustum::raw_planes(pair);
    const std::pair<const frustum::Plane<double>*, Vec4 UnitPlanes::*> sides[5] = {
        {&raw.left, &UnitPlanes::left}, {&raw.right, &UnitPlanes::right}, {&raw.bottom, &UnitPlanes::bottom},
        {&raw.top, &UnitPlanes::top},   {&raw.near, &UnitPlanes::near}};
    const char* names[5] = {"left", "right", "bottom", "top", "near"};
    UnitPlanes out;
    for (int i = 0; i < 5; ++i) {
        const auto unit = unit_plane(*sides[i].first, names[i]);
        if (!unit) {
            return unit.take_error();
        }
        out.*(sides[i].second) = *unit;
    }
    if (raw.far) {
        const auto unit = unit_plane(*raw.far, "far");
        if (!unit) {
            return unit.take_error();
        }
        out.far = *unit;
    }
    return out;
}

// n . p + d >= -tolerance (|p| + |d|) for every unit plane.
bool inside(const UnitPlanes& planes, const Vec3& p) {
    const auto holds = [&p](const Vec4& plane) {
        const double value = glm::dot(Vec3(plane), p) + plane.w;
        return value >= -kInsideTolerance * (std::hypot(p.x, p.y, p.z) + std::abs(plane.w));
    };
    return holds(planes.left) && holds(planes.right) && holds(planes.bottom) && holds(planes.top) &&
           holds(planes.near) && (!planes.far || holds(*planes.far));
}

// A point as the contract prints it: w = 1, or w = 0 with a unit xyz.
// frustum::to_point gives (0, 0, 0, 0) when |xyz| overflows a double.
bool canonical(const Vec4& p) {
    return finite(p) && (p.w == 1.0 || (p.w == 0.0 && std::abs(glm::length(Vec3(p)) - 1.0) < 1e-9));
}

// The first field of an answer that is not finite (or, for points, not in
// canonical form), or nullptr.
const char* non_finite_field(const Answer& a) {
    if (!finite(a.matrix)) return "matrix";
    if (!finite(a.inverse)) return "inverse";
    for (const Vec4& c : a.corners) {
        if (!canonical(c)) return "corners";
    }
    if (!canonical(a.center)) return "center";
    if (!canonical(a.eye) || !canonical(a.vanishing_y) || !canonical(a.vanishing_x)) return "vanishing";
    if (a.clip) {
        for (const Vec4& c : *a.clip) {
            if (!finite(c)) return "clip";
        }
    }
    return nullptr; // planes are checked when normalized
}

std::string text(const Vec3& p) {
    std::string out = "(";
    for (int i = 0; i < 3; ++i) {
        out += frustum::detail::number(p[i]);
        out += i < 2 ? ", " : ")";
    }
    return out;
}

Outcome failure(const std::string& id, std::string error) { return Outcome{id, std::nullopt, std::move(error)}; }

// The case's camera, composed with its view (M = P V), then its ops in order.
PairResult case_pair(const Case& c) {
    auto pair = make_camera(c.camera, c.depth);
    if (!pair) {
        return frustum::Error{std::string("camera.") + camera_name(c.camera) + ": " + pair.error()};
    }
    if (c.view) {
        const auto view = frustum::look_at(c.view->eye, c.view->target, c.view->up);
        if (!view) {
            return frustum::Error{"view: " + view.error()};
        }
        pair = frustum::compose(*pair, *view); // M = P V
    }
    for (std::size_t i = 0; i < c.ops.size(); ++i) {
        auto next = apply_op(*pair, c.ops[i]);
        if (!next) {
            return frustum::Error{"ops[" + std::to_string(i) + "]." + op_key(c.ops[i]) + ": " + next.error()};
        }
        pair = std::move(next);
    }
    return pair;
}

// What every answer has: the matrix and its inverse, the unit planes, the
// key points and the validity.
frustum::Status answer_pair(const Pair& pair, Answer& a) {
    a.matrix = pair.matrix();
    a.inverse = pair.inverse();
    if (!finite(a.matrix) || !finite(a.inverse)) {
        return frustum::Error{std::string("result: ") + (finite(a.matrix) ? "inverse" : "matrix") +
                              " has a non-finite entry (the frustum is too large or too thin to represent)"};
    }
    auto planes = unit_planes(pair);
    if (!planes) {
        return frustum::Error{planes.error()};
    }
    a.planes = *planes;

    const double tolerance = frustum::infinity_tolerance<double>();
    const frustum::KeyPoints<double> points = frustum::key_points(pair);
    for (int i = 0; i < 8; ++i) {
        a.corners[static_cast<std::size_t>(i)] = frustum::to_point(points.corners[static_cast<std::size_t>(i)], tolerance);
    }
    a.center = frustum::to_point(points.center, tolerance);
    a.eye = frustum::to_point(points.eye, tolerance);
    a.vanishing_y = frustum::to_point(points.vanishing_y, tolerance);
    a.vanishing_x = frustum::to_point(points.vanishing_x, tolerance);
    a.valid = frustum::validate(pair).valid();
    return {};
}

// "points": M [p, 1] and the inside test of each (after answer_pair()).
frustum::Status answer_points(const std::vector<Vec3>& points, Answer& a) {
    a.clip.emplace();
    a.inside.emplace();
    for (std::size_t i = 0; i < points.size(); ++i) {
        const Vec3& p = points[i];
        if (!finite(Vec4(p, 1.0))) {
            return frustum::Error{"points[" + std::to_string(i) + "]: coordinates must be finite, got " + text(p)};
        }
        a.clip->push_back(a.matrix * Vec4(p, 1.0));
        a.inside->push_back(inside(a.planes, p));
    }
    return {};
}

// "rects": each polygon's pixel rectangle.
frustum::Status answer_rects(const Pair& pair, const std::vector<RectQuery>& rects, Answer& a) {
    a.screen_rects.emplace();
    for (std::size_t i = 0; i < rects.size(); ++i) {
        const RectQuery& q = rects[i];
        const auto rect = frustum::screen_rect(pair, q.corners, q.full_width, q.full_height);
        if (!rect) {
            return frustum::Error{"rects[" + std::to_string(i) + "]: " + rect.error()};
        }
        a.screen_rects->push_back(*rect);
    }
    return {};
}

// "boxes": each box's cull word.
frustum::Status answer_boxes(const Pair& pair, const std::vector<BoxQuery>& boxes, Answer& a) {
    a.cull.emplace();
    const frustum::FrustumPlanes<double> unit = frustum::planes(pair);
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        const BoxQuery& b = boxes[i];
        if (!finite(Vec4(b.min, 1.0)) || !finite(Vec4(b.max, 1.0))) {
            return frustum::Error{"boxes[" + std::to_string(i) + "]: min and max must be finite, got min=" +
                                  text(b.min) + " max=" + text(b.max)};
        }
        if (!(b.min.x <= b.max.x && b.min.y <= b.max.y && b.min.z <= b.max.z)) {
            return frustum::Error{"boxes[" + std::to_string(i) + "]: min must not exceed max, got min=" +
                                  text(b.min) + " max=" + text(b.max)};
        }
        a.cull->push_back(frustum::to_string(frustum::classify(unit, frustum::Aabb<double>{b.min, b.max})));
    }
    return {};
}

// The answer of a case whose pair was built: every part it asks for, in
// the contract's order, then the check that all of it is representable.
frustum::Result<Answer> answer_case(const Case& c, const Pair& pair) {
    Answer a;
    frustum::Status status = answer_pair(pair, a);
    if (status && c.points) {
        status = answer_points(*c.points, a);
    }
    if (status && c.rects) {
        status = answer_rects(pair, *c.rects, a);
    }
    if (status && c.boxes) {
        status = answer_boxes(pair, *c.boxes, a);
    }
    if (!status) {
        return status.take_error();
    }
    if (const char* field = non_finite_field(a)) {
        return frustum::Error{std::string("result: ") + field +
                              " is not representable in double (the frustum is too large or too thin)"};
    }
    return a;
}

} // namespace

Outcome evaluate_case(const Case& c) {
    const auto pair = case_pair(c);
    if (!pair) {
        return failure(c.id, pair.error());
    }
    auto answer = answer_case(c, *pair);
    if (!answer) {
        return failure(c.id, answer.error());
    }
    return Outcome{c.id, std::move(*answer), {}};
}

} // namespace vectors
