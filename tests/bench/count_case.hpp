// What the instruction-count drivers of scripts/count-instructions.sh share
// (count_driver.cpp, count_tiles_driver.cpp): the fixed camera every counted
// case starts from, a barrier that keeps the compiler from folding the case
// into constants, and the op-name lookup.
#pragma once

#include <frustum/frustum.hpp>

#include <cstring>
#include <optional>
#include <string>

namespace bench {

// Keeps the compiler from folding the case into constants or dropping the
// result (the operands live in memory it cannot see through).
template <class V>
void keep(V& value) {
    asm volatile("" : : "r"(&value) : "memory");
}

// 1 rad vertical field of view, 16:9, near 0.1 m, far 100 m, [0, 1] depth,
// from (0, 1, 3) looking at (0, 0.8, 0).
inline frustum::Result<frustum::MatrixPair<float>> count_camera() {
    const auto projection = frustum::perspective(1.0f, 16.0f / 9.0f, 0.1f, std::optional<float>(100.0f),
                                                 frustum::DepthRange::ZeroToOne);
    const auto view =
        frustum::look_at(glm::vec3(0.0f, 1.0f, 3.0f), glm::vec3(0.0f, 0.8f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    if (!projection || !view) {
        return frustum::Error{(projection ? std::string() : projection.error()) + (view ? std::string() : view.error())};
    }
    return frustum::compose(*projection, *view);
}

// Index of `op` in `names`, -1 when it is none of them.
template <std::size_t N>
int op_index(const char* op, const char* const (&names)[N]) {
    for (std::size_t k = 0; k < N; ++k) {
        if (std::strcmp(op, names[k]) == 0) {
            return static_cast<int>(k);
        }
    }
    return -1;
}

} // namespace bench
