// The typed form of a frustum-vectors request (docs/vectors-contract.md).
// Plain data, filled by parse_request() and read by evaluate(); numbers are
// exactly as given (they may be infinite: "1e999" is a geometric error of
// its case, found by the library, not a malformed request).
#pragma once

#include <frustum/depth_range.hpp>
#include <frustum/mirror.hpp>
#include <frustum/types.hpp>

#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace vectors {

using Vec3 = frustum::Vec3<double>;
using Vec4 = frustum::Vec4<double>;
using Mat4 = frustum::Mat4<double>;

// "perspective": VERTICAL field of view in degrees (converted to radians
// only when the library is called), aspect = width / height.
struct PerspectiveCamera {
    double fovy_deg = 0, aspect = 0, near_m = 0;
    std::optional<double> far_m; // JSON null: infinite far plane
};

// "frustum": glFrustum's near-plane rectangle at distance near_m.
struct FrustumCamera {
    double left = 0, right = 0, bottom = 0, top = 0, near_m = 0;
    std::optional<double> far_m; // JSON null: infinite far plane
};

// "ortho": the box [left, right] x [bottom, top] x [-far, -near].
struct OrthoCamera {
    double left = 0, right = 0, bottom = 0, top = 0, near_m = 0, far_m = 0;
};

// "planes" (paper §4): five world-space planes [a, b, c, d], and either a
// far point (§4.1) or the corrected volume-growth loop (§4.2, far: "volume").
struct PlanesCamera {
    Vec4 left{0}, right{0}, bottom{0}, top{0}, near{0};
    std::optional<Vec3> far_point; // empty: far: "volume"
};

// "mirror_rect" (paper §5.3): the view from the reflected eye through the
// rectangle corner, corner + a1, corner + a1 + a2, corner + a2.
struct MirrorRectCamera {
    Vec3 corner{0}, a1{0}, a2{0}, eye{0};
    double far_m = 0;
    frustum::MirrorFit fit = frustum::MirrorFit::Paper;
};

// "matrix": 16 numbers, column-major as GLM stores them (clip = M * p).
struct MatrixCamera {
    Mat4 matrix{1};
};

using Camera = std::variant<PerspectiveCamera, FrustumCamera, OrthoCamera, PlanesCamera, MirrorRectCamera, MatrixCamera>;

struct View {
    Vec3 eye{0}, target{0}, up{0};
};

// "crop" (§5.1): offset from the BOTTOM-left corner, any consistent unit.
struct CropOp {
    double x = 0, y = 0, width = 0, height = 0, full_width = 0, full_height = 0;
};

// "reflect", "clip" and "mirror" (§5.2): a world-space plane a x + b y + c z + d = 0.
struct PlaneOp {
    enum class Kind { Reflect, Clip, Mirror };
    Kind kind = Kind::Reflect;
    Vec4 plane{0};
};

// "jitter" (version 2): the image shifted by (dx, dy) pixels of a
// full_width x full_height image.
struct JitterOp {
    double dx = 0, dy = 0, full_width = 0, full_height = 0;
};

// "portal" (version 2): a frame is an origin and unit, orthogonal x and y.
struct FrameSpec {
    Vec3 origin{0}, x{0}, y{0};
};
struct PortalOp {
    FrameSpec entry, exit;
};

using Op = std::variant<CropOp, PlaneOp, JitterOp, PortalOp>;

// Case-level "rects" (version 2): a convex planar polygon in world space
// and the image it is measured in; answered by "screen_rects".
struct RectQuery {
    std::vector<Vec3> corners;
    double full_width = 0, full_height = 0;
};

// Case-level "boxes" (version 2): an axis-aligned box; answered by "cull".
struct BoxQuery {
    Vec3 min{0}, max{0};
};

struct Case {
    std::string id;
    frustum::DepthRange depth = frustum::DepthRange::ZeroToOne;
    Camera camera;
    std::optional<View> view;              // absent: identity
    std::vector<Op> ops;                   // applied in order
    std::optional<std::vector<Vec3>> points; // absent: no "clip"/"inside" in the answer
    std::optional<std::vector<RectQuery>> rects; // absent: no "screen_rects"
    std::optional<std::vector<BoxQuery>> boxes;  // absent: no "cull"
};

struct Request {
    std::vector<Case> cases;
};

// The JSON name of an op kind: "reflect", "clip" or "mirror".
const char* op_name(PlaneOp::Kind kind);

} // namespace vectors
