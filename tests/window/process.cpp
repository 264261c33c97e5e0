#include "process.hpp"

#include <cstdlib>
#include <sstream>

#include <unistd.h>

namespace window_test {

Child run(const std::string& program, const std::vector<std::string>& args,
          const std::map<std::string, std::optional<std::string>>& environment, int timeout_s) {
    support::Launch launch;
    launch.args = args;
    launch.environment = environment;
    launch.timeout_s = timeout_s;
    return support::run(program, launch);
}

std::string find_on_path(const std::string& name) {
    const char* path = std::getenv("PATH");
    std::istringstream folders(path != nullptr ? path : "");
    for (std::string folder; std::getline(folders, folder, ':');) {
        const std::filesystem::path candidate = std::filesystem::path(folder.empty() ? "." : folder) / name;
        if (::access(candidate.c_str(), X_OK) == 0) {
            return candidate.string();
        }
    }
    return {};
}

} // namespace window_test
