#include "frustum/jitter.hpp"

#include "frustum/detail/errors.hpp"
#include "frustum/detail/pair_factory.hpp"

#include <cmath>

namespace frustum {

template <class T>
Result<MatrixPair<T>> jitter(const MatrixPair<T>& pair, T dx_px, T dy_px, T width_px, T height_px) {
    if (!std::isfinite(dx_px) || !std::isfinite(dy_px) || !std::isfinite(width_px) || !std::isfinite(height_px) ||
        !(width_px > T(0)) || !(height_px > T(0))) {
        return detail::error<T>("jitter", "offsets must be finite and image sizes finite and > 0",
                                {{"dx_px", dx_px}, {"dy_px", dy_px}, {"width_px", width_px}, {"height_px", height_px}});
    }
    const T tx = T(2) * dx_px / width_px, ty = T(2) * dy_px / height_px;
    // M' = J M: entry (0, j) += tx m_3j, (1, j) += ty m_3j, column by column.
    Mat4<T> m = pair.matrix();
    for (int j = 0; j < 4; ++j) {
        m[j].x += tx * m[j].w;
        m[j].y += ty * m[j].w;
    }
    // M'^-1 = M^-1 J^-1: only column 3 changes.
    Mat4<T> inv = pair.inverse();
    inv[3] = pair.inverse()[3] - tx * pair.inverse()[0] - ty * pair.inverse()[1];
    return detail::PairFactory::keep_sign(m, inv, pair.depth(), pair.flips_winding());
}

template Result<MatrixPair<float>> jitter(const MatrixPair<float>&, float, float, float, float);
template Result<MatrixPair<double>> jitter(const MatrixPair<double>&, double, double, double, double);

} // namespace frustum
