#include "vectors/response.hpp"

namespace vectors {

namespace {

using nlohmann::ordered_json;

ordered_json vec4(const Vec4& v) { return ordered_json::array({v.x, v.y, v.z, v.w}); }

// Column-major: m[0][0], m[0][1], ... (GLM's memory order).
ordered_json mat4(const Mat4& m) {
    ordered_json out = ordered_json::array();
    for (int column = 0; column < 4; ++column) {
        for (int row = 0; row < 4; ++row) {
            out.push_back(m[column][row]);
        }
    }
    return out;
}

// Appends the answer's keys to `out` (after id and ok), in contract order.
void append_answer(ordered_json& out, const Answer& a) {
    out["matrix"] = mat4(a.matrix);
    out["inverse"] = mat4(a.inverse);
    ordered_json planes = ordered_json::object();
    planes["left"] = vec4(a.planes.left);
    planes["right"] = vec4(a.planes.right);
    planes["bottom"] = vec4(a.planes.bottom);
    planes["top"] = vec4(a.planes.top);
    planes["near"] = vec4(a.planes.near);
    planes["far"] = a.planes.far ? vec4(*a.planes.far) : ordered_json(nullptr);
    out["planes"] = std::move(planes);
    ordered_json corners = ordered_json::array();
    for (const Vec4& c : a.corners) {
        corners.push_back(vec4(c));
    }
    out["corners"] = std::move(corners);
    out["center"] = vec4(a.center);
    ordered_json vanishing = ordered_json::object();
    vanishing["O"] = vec4(a.eye);
    vanishing["O1"] = vec4(a.vanishing_y);
    vanishing["O2"] = vec4(a.vanishing_x);
    out["vanishing"] = std::move(vanishing);
    out["valid"] = a.valid;
    if (a.clip && a.inside) {
        ordered_json clip = ordered_json::array();
        for (const Vec4& c : *a.clip) {
            clip.push_back(vec4(c));
        }
        out["clip"] = std::move(clip);
        ordered_json inside = ordered_json::array();
        for (const bool b : *a.inside) {
            inside.push_back(b);
        }
        out["inside"] = std::move(inside);
    }
    if (a.screen_rects) {
        ordered_json rects = ordered_json::array();
        for (const auto& r : *a.screen_rects) {
            if (!r) {
                rects.push_back(nullptr);
                continue;
            }
            ordered_json rect = ordered_json::object();
            rect["x"] = r->x;
            rect["y"] = r->y;
            rect["width"] = r->width;
            rect["height"] = r->height;
            rects.push_back(std::move(rect));
        }
        out["screen_rects"] = std::move(rects);
    }
    if (a.cull) {
        out["cull"] = *a.cull;
    }
}

} // namespace

nlohmann::ordered_json response_json(const std::vector<Outcome>& outcomes) {
    ordered_json cases = ordered_json::array();
    for (const Outcome& o : outcomes) {
        ordered_json c = ordered_json::object();
        c["id"] = o.id;
        c["ok"] = o.answer.has_value();
        if (o.answer) {
            append_answer(c, *o.answer);
        } else {
            c["error"] = o.error;
        }
        cases.push_back(std::move(c));
    }
    ordered_json document = ordered_json::object();
    document["cases"] = std::move(cases);
    return document;
}

} // namespace vectors
