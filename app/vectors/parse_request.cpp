#include "vectors/parse_request.hpp"

#include <frustum/detail/enum_names.hpp>

#include <array>
#include <cstddef>
#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>

namespace vectors {

const char* op_name(PlaneOp::Kind kind) {
    constexpr frustum::detail::EnumName<PlaneOp::Kind> kNames[] = {
        {PlaneOp::Kind::Reflect, "reflect"}, {PlaneOp::Kind::Clip, "clip"}, {PlaneOp::Kind::Mirror, "mirror"}};
    const char* name = frustum::detail::find_enum_name(kNames, kind);
    return name ? name : "?";
}

namespace {

using nlohmann::json;
using Keys = std::initializer_list<std::string_view>;

// Thrown inside this file only; parse_request turns it into an Error.
struct ShapeError {
    std::string path;
    std::string what;
};

[[noreturn]] void fail(const std::string& path, std::string what) { throw ShapeError{path, std::move(what)}; }

std::string child(const std::string& path, std::string_view key) {
    return path.empty() ? std::string(key) : path + "." + std::string(key);
}

std::string element(const std::string& path, std::size_t i) { return path + "[" + std::to_string(i) + "]"; }

std::string join(Keys keys, std::string_view last_separator = ", ") {
    std::string text;
    std::size_t i = 0;
    for (std::string_view key : keys) {
        if (i > 0) {
            text += i + 1 == keys.size() ? last_separator : std::string_view(", ");
        }
        text += key;
        ++i;
    }
    return text;
}

bool contains(Keys keys, std::string_view key) {
    for (std::string_view k : keys) {
        if (k == key) {
            return true;
        }
    }
    return false;
}

// An object whose keys all belong to `allowed`.
const json& object(const json& value, const std::string& path, Keys allowed) {
    if (!value.is_object()) {
        fail(path, std::string("expected an object, got ") + value.type_name());
    }
    for (const auto& item : value.items()) {
        if (!contains(allowed, item.key())) {
            fail(child(path, item.key()), "unknown key (expected one of " + join(allowed) + ")");
        }
    }
    return value;
}

const json& required(const json& object, const std::string& path, std::string_view key) {
    const auto it = object.find(key);
    if (it == object.end()) {
        fail(child(path, key), "missing required key");
    }
    return *it;
}

const json* optional(const json& object, std::string_view key) {
    const auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
}

double number(const json& value, const std::string& path) {
    if (!value.is_number()) {
        fail(path, std::string("expected a number, got ") + value.type_name());
    }
    return value.get<double>();
}

double number_at(const json& object, const std::string& path, std::string_view key) {
    return number(required(object, path, key), child(path, key));
}

// A number, or null for an infinite far plane.
std::optional<double> far_at(const json& object, const std::string& path) {
    const json& value = required(object, path, "far");
    if (value.is_null()) {
        return std::nullopt;
    }
    if (!value.is_number()) {
        fail(child(path, "far"), std::string("expected a number or null, got ") + value.type_name());
    }
    return value.get<double>();
}

std::string string(const json& value, const std::string& path) {
    if (!value.is_string()) {
        fail(path, std::string("expected a string, got ") + value.type_name());
    }
    return value.get<std::string>();
}

template <std::size_t N>
std::array<double, N> numbers(const json& value, const std::string& path) {
    const std::string expected = "expected an array of " + std::to_string(N) + " numbers";
    if (!value.is_array()) {
        fail(path, expected + ", got " + value.type_name());
    }
    if (value.size() != N) {
        fail(path, expected + ", got " + std::to_string(value.size()) + " elements");
    }
    std::array<double, N> out{};
    for (std::size_t i = 0; i < N; ++i) {
        out[i] = number(value[i], element(path, i));
    }
    return out;
}

Vec3 vec3(const json& value, const std::string& path) {
    const auto a = numbers<3>(value, path);
    return Vec3(a[0], a[1], a[2]);
}

Vec3 vec3_at(const json& object, const std::string& path, std::string_view key) {
    return vec3(required(object, path, key), child(path, key));
}

Vec4 plane_at(const json& object, const std::string& path, std::string_view key) {
    const auto a = numbers<4>(required(object, path, key), child(path, key));
    return Vec4(a[0], a[1], a[2], a[3]);
}

// The single key of an object that must hold exactly one of `kinds`.
std::string one_kind(const json& value, const std::string& path, Keys kinds) {
    object(value, path, kinds);
    if (value.size() != 1) {
        std::string got = value.empty() ? "none" : std::to_string(value.size()) + ":";
        std::string separator = " ";
        for (const auto& item : value.items()) {
            got += separator + item.key();
            separator = ", ";
        }
        fail(path, "expected exactly one of " + join(kinds) + ", got " + got);
    }
    return value.begin().key();
}

frustum::DepthRange depth_range(const json& value, const std::string& path) {
    const std::string name = string(value, path);
    for (auto depth : {frustum::DepthRange::ZeroToOne, frustum::DepthRange::MinusOneToOne,
                       frustum::DepthRange::ReversedZeroToOne}) {
        if (name == frustum::to_string(depth)) {
            return depth;
        }
    }
    fail(path, "unknown depth range \"" + name + "\" (expected zero_to_one, minus_one_to_one or reversed_zero_to_one)");
}

Camera perspective(const json& value, const std::string& path) {
    object(value, path, {"fovy_deg", "aspect", "near", "far"});
    PerspectiveCamera c;
    c.fovy_deg = number_at(value, path, "fovy_deg");
    c.aspect = number_at(value, path, "aspect");
    c.near_m = number_at(value, path, "near");
    c.far_m = far_at(value, path);
    return c;
}

// "left", "right", "bottom", "top" into the fields of those names, each read(value, path, key).
template <class Sides, class Read>
void sides_at(Sides& c, const json& value, const std::string& path, const Read& read) {
    c.left = read(value, path, "left");
    c.right = read(value, path, "right");
    c.bottom = read(value, path, "bottom");
    c.top = read(value, path, "top");
}

// frustum and ortho: the same six keys, "far" read by read_far (a frustum's may be infinite: far_at()).
template <class BoxCamera, class ReadFar>
Camera box_camera(const json& value, const std::string& path, const ReadFar& read_far) {
    object(value, path, {"left", "right", "bottom", "top", "near", "far"});
    BoxCamera c;
    sides_at(c, value, path, number_at);
    c.near_m = number_at(value, path, "near");
    c.far_m = read_far(value, path);
    return c;
}

Camera planes(const json& value, const std::string& path) {
    object(value, path, {"left", "right", "bottom", "top", "near", "far_point", "far"});
    PlanesCamera c;
    sides_at(c, value, path, plane_at);
    c.near = plane_at(value, path, "near");
    const json* far_point = optional(value, "far_point");
    const json* far = optional(value, "far");
    if ((far_point == nullptr) == (far == nullptr)) {
        fail(path, "expected exactly one of far_point ([x, y, z]) and far (\"volume\")");
    }
    if (far_point) {
        c.far_point = vec3(*far_point, child(path, "far_point"));
    } else if (string(*far, child(path, "far")) != "volume") {
        fail(child(path, "far"), "expected \"volume\" (or give far_point instead)");
    }
    return c;
}

Camera mirror_rect(const json& value, const std::string& path) {
    object(value, path, {"corner", "a1", "a2", "eye", "far", "fit"});
    MirrorRectCamera c;
    c.corner = vec3_at(value, path, "corner");
    c.a1 = vec3_at(value, path, "a1");
    c.a2 = vec3_at(value, path, "a2");
    c.eye = vec3_at(value, path, "eye");
    c.far_m = number_at(value, path, "far");
    const std::string fit = string(required(value, path, "fit"), child(path, "fit"));
    if (fit == "paper") {
        c.fit = frustum::MirrorFit::Paper;
    } else if (fit == "exact") {
        c.fit = frustum::MirrorFit::Exact;
    } else {
        fail(child(path, "fit"), "expected \"paper\" or \"exact\", got \"" + fit + "\"");
    }
    return c;
}

Camera matrix(const json& value, const std::string& path) {
    const auto a = numbers<16>(value, path);
    MatrixCamera c;
    for (int column = 0; column < 4; ++column) {
        for (int row = 0; row < 4; ++row) {
            c.matrix[column][row] = a[static_cast<std::size_t>(4 * column + row)]; // column-major, as GLM
        }
    }
    return c;
}

Camera camera(const json& value, const std::string& path) {
    const std::string kind = one_kind(value, path, {"perspective", "frustum", "ortho", "planes", "mirror_rect", "matrix"});
    const json& body = value.front();
    const std::string body_path = child(path, kind);
    if (kind == "perspective") return perspective(body, body_path);
    if (kind == "frustum") return box_camera<FrustumCamera>(body, body_path, far_at);
    if (kind == "ortho") {
        return box_camera<OrthoCamera>(body, body_path,
                                       [](const json& v, const std::string& p) { return number_at(v, p, "far"); });
    }
    if (kind == "planes") return planes(body, body_path);
    if (kind == "mirror_rect") return mirror_rect(body, body_path);
    return matrix(body, body_path);
}

// Cameras that are already in world space and take no view.
const char* world_space_camera(const Camera& camera) {
    if (std::holds_alternative<PlanesCamera>(camera)) return "planes";
    if (std::holds_alternative<MirrorRectCamera>(camera)) return "mirror_rect";
    if (std::holds_alternative<MatrixCamera>(camera)) return "matrix";
    return nullptr;
}

View view(const json& value, const std::string& path) {
    object(value, path, {"eye", "target", "up"});
    return View{vec3_at(value, path, "eye"), vec3_at(value, path, "target"), vec3_at(value, path, "up")};
}

FrameSpec frame(const json& value, const std::string& path) {
    object(value, path, {"origin", "x", "y"});
    return FrameSpec{vec3_at(value, path, "origin"), vec3_at(value, path, "x"), vec3_at(value, path, "y")};
}

Op op(const json& value, const std::string& path) {
    const std::string kind = one_kind(value, path, {"crop", "reflect", "clip", "mirror", "jitter", "portal"});
    const json& body = value.front();
    const std::string body_path = child(path, kind);
    if (kind == "jitter") {
        object(body, body_path, {"dx", "dy", "full_width", "full_height"});
        JitterOp j;
        j.dx = number_at(body, body_path, "dx");
        j.dy = number_at(body, body_path, "dy");
        j.full_width = number_at(body, body_path, "full_width");
        j.full_height = number_at(body, body_path, "full_height");
        return j;
    }
    if (kind == "portal") {
        object(body, body_path, {"entry", "exit"});
        return PortalOp{frame(required(body, body_path, "entry"), child(body_path, "entry")),
                        frame(required(body, body_path, "exit"), child(body_path, "exit"))};
    }
    if (kind == "crop") {
        object(body, body_path, {"x", "y", "width", "height", "full_width", "full_height"});
        CropOp c;
        c.x = number_at(body, body_path, "x");
        c.y = number_at(body, body_path, "y");
        c.width = number_at(body, body_path, "width");
        c.height = number_at(body, body_path, "height");
        c.full_width = number_at(body, body_path, "full_width");
        c.full_height = number_at(body, body_path, "full_height");
        return c;
    }
    object(body, body_path, {"plane"});
    PlaneOp p;
    p.kind = kind == "reflect" ? PlaneOp::Kind::Reflect
             : kind == "clip"  ? PlaneOp::Kind::Clip
                               : PlaneOp::Kind::Mirror;
    p.plane = plane_at(body, body_path, "plane");
    return p;
}

const json& array(const json& value, const std::string& path) {
    if (!value.is_array()) {
        fail(path, std::string("expected an array, got ") + value.type_name());
    }
    return value;
}

RectQuery rect_query(const json& value, const std::string& path) {
    object(value, path, {"corners", "full_width", "full_height"});
    RectQuery r;
    const std::string corners_path = child(path, "corners");
    const json& corners = array(required(value, path, "corners"), corners_path);
    if (corners.size() < 3) {
        fail(corners_path, "expected an array of 3 or more points, got " + std::to_string(corners.size()) + " elements");
    }
    for (std::size_t i = 0; i < corners.size(); ++i) {
        r.corners.push_back(vec3(corners[i], element(corners_path, i)));
    }
    r.full_width = number_at(value, path, "full_width");
    r.full_height = number_at(value, path, "full_height");
    return r;
}

BoxQuery box_query(const json& value, const std::string& path) {
    object(value, path, {"min", "max"});
    return BoxQuery{vec3_at(value, path, "min"), vec3_at(value, path, "max")};
}

Case one_case(const json& value, const std::string& path) {
    object(value, path, {"id", "depth", "camera", "view", "ops", "points", "rects", "boxes"});
    Case c;
    c.id = string(required(value, path, "id"), child(path, "id"));
    if (const json* depth = optional(value, "depth")) {
        c.depth = depth_range(*depth, child(path, "depth"));
    }
    c.camera = camera(required(value, path, "camera"), child(path, "camera"));
    if (const json* v = optional(value, "view")) {
        if (const char* kind = world_space_camera(c.camera)) {
            fail(child(path, "view"), std::string("not allowed with camera \"") + kind +
                                          "\", which is already in world space");
        }
        c.view = view(*v, child(path, "view"));
    }
    if (const json* ops = optional(value, "ops")) {
        const std::string ops_path = child(path, "ops");
        for (std::size_t i = 0; i < array(*ops, ops_path).size(); ++i) {
            c.ops.push_back(op((*ops)[i], element(ops_path, i)));
        }
    }
    if (const json* points = optional(value, "points")) {
        const std::string points_path = child(path, "points");
        c.points.emplace();
        for (std::size_t i = 0; i < array(*points, points_path).size(); ++i) {
            c.points->push_back(vec3((*points)[i], element(points_path, i)));
        }
    }
    if (const json* rects = optional(value, "rects")) {
        const std::string rects_path = child(path, "rects");
        c.rects.emplace();
        for (std::size_t i = 0; i < array(*rects, rects_path).size(); ++i) {
            c.rects->push_back(rect_query((*rects)[i], element(rects_path, i)));
        }
    }
    if (const json* boxes = optional(value, "boxes")) {
        const std::string boxes_path = child(path, "boxes");
        c.boxes.emplace();
        for (std::size_t i = 0; i < array(*boxes, boxes_path).size(); ++i) {
            c.boxes->push_back(box_query((*boxes)[i], element(boxes_path, i)));
        }
    }
    return c;
}

} // namespace

frustum::Result<Request> parse_request(const nlohmann::json& document) {
    try {
        object(document, "", {"cases"});
        const json& cases = array(required(document, "", "cases"), "cases");
        Request request;
        request.cases.reserve(cases.size());
        for (std::size_t i = 0; i < cases.size(); ++i) {
            request.cases.push_back(one_case(cases[i], element("cases", i)));
        }
        return request;
    } catch (const ShapeError& e) {
        return frustum::Error{(e.path.empty() ? std::string("(document)") : e.path) + ": " + e.what};
    }
}

} // namespace vectors
