// Accuracy of the analytic inverse updates (paper §5.1-5.3) in float,
// against re-inverting with glm::inverse, both measured against a
// double-precision reference (the same operation in double, inverted with
// glm::inverse in double). Prints a Markdown table for docs/performance.md.
//
//   ops_accuracy [cases per depth range, default 100000]
//
// Error of one inverse: max over its columns of |col - ref| / |ref|
// (columns are points of very different sizes, so each is judged alone),
// up to the overall sign.
#include "accuracy_measures.hpp"
#include "random_cases.hpp"
#include "reinvert.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

namespace {

using frustum::DepthRange;
using frustum::Mat4;
using frustum::MatrixPair;
using frustum::Plane;

using bench::column_error;
using bench::pair_residual;

using bench::Stats;

// The paper's clip update read literally (eq. 20-27 in column form): Q from
// the inverse, k = (m3 . Q) / (c . Q), X = k M^-T c, then T^-1.
template <class T>
Mat4<T> paper_literal_clip_inverse(const MatrixPair<T>& pair, const Plane<T>& unit_plane) {
    const auto& inv = pair.inverse();
    const frustum::Vec4<T> c = unit_plane.abcd;
    const frustum::Vec4<T> c_clip = glm::transpose(inv) * c;
    const frustum::Vec4<T> q(c_clip.x >= 0 ? 1 : -1, c_clip.y >= 0 ? 1 : -1,
                             frustum::clip_z_far<T>(pair.depth()), 1);
    const frustum::Vec4<T> big_q = inv * q;
    const T k = glm::dot(frustum::row(pair.matrix(), 3), big_q) / glm::dot(c, big_q);
    const T span = frustum::clip_z_span<T>(pair.depth());
    const frustum::Vec4<T> x = span * k * c_clip + frustum::Vec4<T>(0, 0, 0, frustum::clip_z_near<T>(pair.depth()));
    Mat4<T> out = inv;
    out[2] = inv[2] / x.z;
    for (int j : {0, 1, 3}) out[j] = inv[j] - (x[j] / x.z) * inv[2];
    return out;
}

template <class T>
Plane<T> unit(const Plane<double>& p) {
    return Plane<T>(frustum::Vec4<T>(p.normalized().abcd));
}

struct Row {
    explicit Row(std::string name) : op(std::move(name)) {}
    std::string op;
    Stats analytic, reinvert, paper;
    bool has_paper = false;
    int rejected = 0; // cases the float operation refused (the double one did not)
    int analytic_not_worse = 0; // cases where analytic error <= glm::inverse error
    Stats analytic_residual, reinvert_residual;
};

// Adds one case's errors; a float operation that refused the case (the
// double one accepted it: the case is borderline in float) is counted apart.
template <class Baseline>
void measure(Row& row, const frustum::Result<MatrixPair<float>>& analytic, const Baseline& baseline,
             const Mat4<double>& reference) {
    if (!analytic) {
        ++row.rejected;
        return;
    }
    const bench::RawPair<float> rebuilt = baseline();
    const double analytic_error = column_error(analytic->inverse(), reference);
    const double baseline_error = column_error(rebuilt.inverse, reference);
    row.analytic_residual.add(pair_residual(analytic->matrix(), analytic->inverse()));
    row.reinvert_residual.add(pair_residual(rebuilt.matrix, rebuilt.inverse));
    row.analytic.add(analytic_error);
    row.reinvert.add(baseline_error);
    row.analytic_not_worse += analytic_error <= baseline_error ? 1 : 0;
}

template <class T>
frustum::CropRect<T> chain_rect() {
    return {T(0.1), T(0.2), T(0.8), T(0.7), T(1), T(1)};
}

// mirror, then crop and reflect alternating: 16 operations.
template <class T>
MatrixPair<T> chain_analytic(const MatrixPair<T>& start, const Plane<T>& mirror_plane, const Plane<T>& a,
                             const Plane<T>& b) {
    MatrixPair<T> p = frustum::mirror(start, mirror_plane).value();
    for (int i = 0; i < 15; ++i) {
        p = (i % 2 == 0) ? frustum::crop(p, chain_rect<T>()).value() : frustum::reflect(p, i % 4 == 1 ? a : b).value();
    }
    return p;
}

bench::RawPair<float> chain_reinvert(const MatrixPair<float>& start, const Plane<float>& mirror_plane,
                                     const Plane<float>& a, const Plane<float>& b, DepthRange depth) {
    bench::RawPair<float> p = bench::mirror_reinvert(bench::raw(start), mirror_plane, depth);
    for (int i = 0; i < 15; ++i) {
        p = (i % 2 == 0) ? bench::crop_reinvert(p, chain_rect<float>())
                         : bench::reflect_reinvert(p, i % 4 == 1 ? a : b);
    }
    return p;
}

void print_row(Row& row, DepthRange depth) {
    const auto cell = [](Stats& s) {
        char text[96];
        std::snprintf(text, sizeof text, "%.2e / %.2e / %.2e / %.2e", s.mean(), s.quantile(0.99), s.quantile(0.999),
                      s.quantile(1.0));
        return std::string(text);
    };
    const double share = 100.0 * row.analytic_not_worse / std::max<std::size_t>(1, row.analytic.errors.size());
    std::printf("| %s | %s | %s | %s | %s | %.1f%% | %d |\n", row.op.c_str(), std::string(frustum::to_string(depth)).c_str(),
                cell(row.analytic).c_str(), cell(row.reinvert).c_str(), row.has_paper ? cell(row.paper).c_str() : "-",
                share, row.rejected);
}

} // namespace

int main(int argc, char** argv) {
    const int count = argc > 1 ? std::atoi(argv[1]) : 100000;
    if (count < 1) {
        std::fprintf(stderr, "ops_accuracy: case count must be >= 1, got %s\n", argv[1]);
        return 2;
    }
    std::printf("Float inverse error vs a double reference, %d random cases per depth range\n"
                "(mean / p99 / p99.9 / max of the worst column's relative error).\n\n", count);
    std::printf("| operation | depth range | analytic (library) | glm::inverse | paper eq. 24-27 literal | cases where analytic <= glm | refused in float |\n");
    std::printf("|---|---|---|---|---|---|---|\n");
    std::vector<std::pair<std::string, std::vector<Row>>> residual_rows;
    for (DepthRange depth : {DepthRange::ZeroToOne, DepthRange::MinusOneToOne, DepthRange::ReversedZeroToOne}) {
        const auto cases = bench::make_mirror_cases(count, depth, 1234u);
        Row crop("crop"), reflect("reflect"), clip("clip_oblique"), mirror("mirror"), rect("mirror_rectangle (exact)"),
            chain("16-op chain");
        clip.has_paper = mirror.has_paper = true;
        const frustum::CropRect<double> crop_rect{100, 50, 320, 180, 1280, 720};
        for (const auto& c : cases) {
            const MatrixPair<float> camera = c.camera.cast<float>();
            const Plane<float> plane = unit<float>(c.mirror_plane);
            const Plane<float> behind = plane.flipped(); // the eye is on its negative side
            const frustum::CropRect<float> crop_rect_f{100, 50, 320, 180, 1280, 720};
            const Plane<double> tilt_a(glm::dvec4(0.6, 0.8, 0.0, -1.0)), tilt_b(glm::dvec4(0.0, 0.28, 0.96, 2.0));

            const auto reference = [](const frustum::Result<MatrixPair<double>>& r) { return glm::inverse(r->matrix()); };
            const auto ref_crop = reference(frustum::crop(c.camera, crop_rect));
            measure(crop, frustum::crop(camera, crop_rect_f),
                    [&] { return bench::crop_reinvert(bench::raw(camera), crop_rect_f); }, ref_crop);

            const auto ref_reflect = reference(frustum::reflect(c.camera, c.mirror_plane));
            measure(reflect, frustum::reflect(camera, plane),
                    [&] { return bench::reflect_reinvert(bench::raw(camera), plane); }, ref_reflect);

            const auto ref_clip = reference(frustum::clip_oblique(c.camera, c.mirror_plane.flipped()));
            const auto clipped = frustum::clip_oblique(camera, behind);
            measure(clip, clipped, [&] { return bench::clip_reinvert(bench::raw(camera), behind, depth); },
                    ref_clip);
            if (clipped) clip.paper.add(column_error(paper_literal_clip_inverse(camera, behind), ref_clip));

            const auto ref_mirror = reference(frustum::mirror(c.camera, c.mirror_plane));
            const auto mirrored = frustum::mirror(camera, plane);
            measure(mirror, mirrored, [&] { return bench::mirror_reinvert(bench::raw(camera), plane, depth); },
                    ref_mirror);
            if (mirrored) {
                mirror.paper.add(column_error(paper_literal_clip_inverse(*frustum::reflect(camera, plane), plane), ref_mirror));
            }

            const auto rect_d = frustum::mirror_rectangle(c.rectangle, c.eye, 100.0, frustum::MirrorFit::Exact, depth);
            if (rect_d) {
                const frustum::Rectangle<float> rect_f{glm::vec3(c.rectangle.corner), glm::vec3(c.rectangle.a1),
                                                       glm::vec3(c.rectangle.a2)};
                const auto rect_pair = frustum::mirror_rectangle(rect_f, glm::vec3(c.eye), 100.0f, frustum::MirrorFit::Exact, depth);
                measure(rect, rect_pair, [&] { return bench::RawPair<float>{rect_pair->matrix(), glm::inverse(rect_pair->matrix())}; },
                        glm::inverse(rect_d->matrix()));
            }

            if (mirrored) {
                const auto ref_chain = glm::inverse(
                    chain_analytic(c.camera, c.mirror_plane, tilt_a.normalized(), tilt_b.normalized()).matrix());
                measure(chain, frustum::Result<MatrixPair<float>>(
                                   chain_analytic(camera, plane, unit<float>(tilt_a), unit<float>(tilt_b))),
                        [&] { return chain_reinvert(camera, plane, unit<float>(tilt_a), unit<float>(tilt_b), depth); },
                        ref_chain);
            } else {
                ++chain.rejected;
            }
        }
        for (Row* row : {&crop, &reflect, &clip, &mirror, &rect, &chain}) {
            print_row(*row, depth);
        }
        residual_rows.push_back({std::string(frustum::to_string(depth)), {crop, reflect, clip, mirror, rect, chain}});
    }
    std::printf("\nPair self-consistency: componentwise residual of M M^-1 = I (mean / max), float.\n\n");
    std::printf("| operation | depth range | analytic pair | M + glm::inverse(M) |\n|---|---|---|---|\n");
    for (auto& [depth_name, rows] : residual_rows) {
        for (Row& row : rows) {
            std::printf("| %s | %s | %.2e / %.2e | %.2e / %.2e |\n", row.op.c_str(), depth_name.c_str(),
                        row.analytic_residual.mean(), row.analytic_residual.quantile(1.0),
                        row.reinvert_residual.mean(), row.reinvert_residual.quantile(1.0));
        }
    }
    return 0;
}
