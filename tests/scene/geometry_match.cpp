#include "geometry_match.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace scene_test {

namespace {

struct Corner {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f}; // unit, world space; zero without normals
    glm::vec2 uv{0.0f};
};

struct Triangle {
    Corner corner[3];
    glm::vec3 centroid{0.0f};
};

std::vector<Triangle> world_triangles(const scene::Scene& s) {
    std::vector<Triangle> out;
    for (const scene::Instance& instance : s.instances) {
        const glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(instance.world)));
        for (const scene::Primitive& p : s.meshes[static_cast<std::size_t>(instance.mesh)].primitives) {
            if (p.mode != scene::PrimitiveMode::Triangles) continue;
            for (std::size_t i = 0; i + 2 < p.indices.size(); i += 3) {
                Triangle t;
                for (int k = 0; k < 3; ++k) {
                    const std::uint32_t v = p.indices[i + std::size_t(k)];
                    Corner& c = t.corner[k];
                    c.position = glm::vec3(instance.world * glm::vec4(p.positions[v], 1.0f));
                    if (!p.normals.empty()) c.normal = glm::normalize(normal_matrix * p.normals[v]);
                    if (!p.texcoords.empty()) c.uv = p.texcoords[v];
                }
                t.centroid = (t.corner[0].position + t.corner[1].position + t.corner[2].position) / 3.0f;
                out.push_back(t);
            }
        }
    }
    return out;
}

float max_abs(glm::vec3 d) { return std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)}); }

// The rotation r (0..2) of b's corners that puts them on a's within the
// tolerance, or -1.
int matching_rotation(const Triangle& a, const Triangle& b, float tolerance) {
    for (int r = 0; r < 3; ++r) {
        bool all = true;
        for (int k = 0; k < 3 && all; ++k) {
            all = max_abs(a.corner[k].position - b.corner[(k + r) % 3].position) <= tolerance;
        }
        if (all) return r;
    }
    return -1;
}

} // namespace

GeometryDifference compare_triangles(const scene::Scene& a, const scene::Scene& b, float position_tolerance_m) {
    const std::vector<Triangle> ta = world_triangles(a);
    std::vector<Triangle> tb = world_triangles(b);
    GeometryDifference d;
    d.triangles_a = ta.size();
    d.triangles_b = tb.size();
    // b sorted by centroid x: the candidates of a triangle are a window.
    std::sort(tb.begin(), tb.end(), [](const Triangle& l, const Triangle& r) { return l.centroid.x < r.centroid.x; });
    std::vector<bool> used(tb.size(), false);
    for (std::size_t i = 0; i < ta.size(); ++i) {
        const Triangle& t = ta[i];
        auto first = std::lower_bound(tb.begin(), tb.end(), t.centroid.x - position_tolerance_m,
                                      [](const Triangle& l, float x) { return l.centroid.x < x; });
        // The closest candidate (positions, then uv: the torus's seams hold
        // triangles at the same place with u = 0 and u = 1).
        std::size_t best = tb.size();
        int best_rotation = -1;
        float best_score = 0.0f;
        for (auto it = first; it != tb.end() && it->centroid.x <= t.centroid.x + position_tolerance_m; ++it) {
            const std::size_t j = std::size_t(it - tb.begin());
            const int r = used[j] ? -1 : matching_rotation(t, *it, position_tolerance_m);
            if (r < 0) continue;
            float score = 0.0f;
            for (int k = 0; k < 3; ++k) {
                const Corner& cb = it->corner[(k + r) % 3];
                score += max_abs(t.corner[k].position - cb.position) + glm::length(t.corner[k].uv - cb.uv);
            }
            if (best == tb.size() || score < best_score) {
                best = j;
                best_rotation = r;
                best_score = score;
            }
        }
        const bool matched = best != tb.size();
        if (matched) {
            used[best] = true;
            for (int k = 0; k < 3; ++k) {
                const Corner& ca = t.corner[k];
                const Corner& cb = tb[best].corner[(k + best_rotation) % 3];
                d.max_position_m = std::max(d.max_position_m, max_abs(ca.position - cb.position));
                d.max_normal = std::max(d.max_normal, glm::length(ca.normal - cb.normal));
                d.max_uv = std::max({d.max_uv, std::abs(ca.uv.x - cb.uv.x), std::abs(ca.uv.y - cb.uv.y)});
            }
        }
        if (!matched) {
            if (d.unmatched == 0) {
                char text[96];
                std::snprintf(text, sizeof text, "triangle %zu at (%g, %g, %g)", i, double(t.centroid.x),
                              double(t.centroid.y), double(t.centroid.z));
                d.first_unmatched = text;
            }
            ++d.unmatched;
        }
    }
    return d;
}

} // namespace scene_test
