// Uses the installed library: a mirror frustum whose inverse is updated
// analytically must still satisfy M * M^-1 = I. Exit 0 on success.
#include <frustum/frustum.hpp>

#include <cmath>
#include <cstdio>

int main() {
    const auto projection = frustum::perspective(1.0f, 1.5f, 0.1f, std::optional<float>(100.0f),
                                                 frustum::DepthRange::ZeroToOne);
    const auto view = frustum::look_at(glm::vec3(0, 2, 5), glm::vec3(0), glm::vec3(0, 1, 0));
    if (!projection || !view) {
        std::fprintf(stderr, "consumer: %s%s\n", projection.error().c_str(), view.error().c_str());
        return 1;
    }
    const auto mirrored = frustum::mirror(frustum::compose(*projection, *view), frustum::Plane<float>(0, 1, 0, 0));
    if (!mirrored) {
        std::fprintf(stderr, "consumer: %s\n", mirrored.error().c_str());
        return 1;
    }
    const glm::mat4 product = mirrored->matrix() * mirrored->inverse();
    float worst = 0.0f;
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            worst = std::fmax(worst, std::fabs(product[c][r] - (c == r ? 1.0f : 0.0f)));
        }
    }
    std::printf("consumer: mirror pair ok, max |M M^-1 - I| = %g\n", worst);
    return worst < 1e-4f ? 0 : 1;
}
