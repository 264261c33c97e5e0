#include "demo/output_dir.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

namespace demo {

frustum::Status prepare_output_dir(const std::string& path) {
    std::error_code error;
    std::filesystem::create_directories(path, error);
    if (error) {
        return frustum::Error{"cannot create output folder '" + path + "': " + error.message()};
    }
    if (!std::filesystem::is_directory(path, error)) {
        return frustum::Error{"output folder '" + path + "' is not a folder"};
    }
    const std::string probe = path + "/.frustum-demo-probe-" + std::to_string(::getpid());
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    if (fd < 0) {
        return frustum::Error{"cannot write to output folder '" + path + "': " + std::strerror(errno)};
    }
    ::close(fd);
    ::unlink(probe.c_str());
    return {};
}

std::vector<std::string> missing_folders(const std::string& path) {
    std::vector<std::string> missing;
    std::error_code error;
    for (std::filesystem::path at = std::filesystem::path(path).lexically_normal();
         !at.empty() && at != at.root_path(); at = at.parent_path()) {
        if (at.filename().empty()) { // "out/" normalizes to "out/" with an empty last name
            continue;
        }
        if (std::filesystem::symlink_status(at, error).type() != std::filesystem::file_type::not_found) {
            break;
        }
        missing.push_back(at.string());
    }
    return missing;
}

void remove_empty_folders(const std::vector<std::string>& folders) {
    for (const std::string& folder : folders) {
        std::error_code error;
        if (!std::filesystem::is_empty(folder, error) || error) {
            return;
        }
        std::filesystem::remove(folder, error); // only ever removes an empty folder
    }
}

} // namespace demo
