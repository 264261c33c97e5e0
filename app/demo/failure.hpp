// How a frustum-demo run ends when it does not succeed.
#pragma once

#include <string>
#include <utility>

namespace demo {

enum class ExitStatus : int {
    Success = 0,
    RuntimeFailure = 1, // the scene, the GL context, the output folder, rendering
    UsageError = 2,     // the command line (including an unknown --camera)
};

// One line, without the "frustum-demo: " prefix main() adds.
struct Failure {
    ExitStatus status;
    std::string message;
};

inline Failure usage(std::string message) { return {ExitStatus::UsageError, std::move(message)}; }
inline Failure runtime(std::string message) { return {ExitStatus::RuntimeFailure, std::move(message)}; }

} // namespace demo
