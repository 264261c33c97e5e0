// The session of lens-report and nonaffine-report (demo/warp_reports.hpp)
// and the two reports, one file each (lens_report.cpp, nonaffine_report.cpp).
#pragma once

#include "demo/report_toolkit.hpp"
#include "demo/session.hpp"
#include "demo/warp_reports.hpp"

#include <gl/offscreen_target.hpp>
#include <render/depth_policy.hpp>
#include <render/scene_pass.hpp>

#include <optional>
#include <variant>

namespace demo {

inline constexpr int kWarpThresholdLsb = 8; // "visibly different" per RGB channel

// The session plus one target of the frame's size and a depth policy for
// the reports' own passes; dies before the session's renderer and context.
struct ReportSession : Session {
    std::optional<render::DepthPolicy> depth;
    std::optional<gl::OffscreenTarget> frame;

    render::PassContext pass() const { return renderer->pass_context(*depth, render::Lighting{}); }

    frustum::Result<image::Image> read() const { return frame->read_rgba8(); }

    // The median of time_runs(), each draw ended by glFinish.
    frustum::Result<double> median_ms(int runs, const std::function<frustum::Status()>& draw) const {
        auto timing = time_runs(runs, [&]() -> frustum::Status {
            auto status = draw();
            fn->Finish();
            return status;
        });
        if (!timing) {
            return frustum::Error{timing.error()};
        }
        return timing->median_ms;
    }

    // A draw that returns a value (Result<T>) as median_ms() times it: the last run's value kept in `value`.
    template <class T, class Draw>
    static std::function<frustum::Status()> keeping(T& value, Draw draw) {
        return [&value, draw]() -> frustum::Status {
            auto drawn = draw();
            if (!drawn) {
                return frustum::Error{drawn.error()};
            }
            value = *drawn;
            return {};
        };
    }

    // median_ms() of `draw`, then the frame it drew (read()).
    struct Timed {
        double median_ms = 0.0;
        image::Image picture;
    };
    frustum::Result<Timed> timed_read(int runs, const std::function<frustum::Status()>& draw) const {
        auto ms = median_ms(runs, draw);
        if (!ms) {
            return frustum::Error{ms.error()};
        }
        auto picture = read();
        if (!picture) {
            return frustum::Error{picture.error()};
        }
        return Timed{*ms, std::move(*picture)};
    }
};

std::variant<WarpReport, Failure> lens_report(const WarpReportRequest& request, ReportSession& s, const Reporter& reporter);
std::variant<WarpReport, Failure> nonaffine_report(const WarpReportRequest& request, ReportSession& s,
                                                   const Reporter& reporter);

} // namespace demo
