#include "process.hpp"

namespace window_test {

Child run(const std::string& program, const std::vector<std::string>& args,
          const std::map<std::string, std::optional<std::string>>& environment, int timeout_s) {
    support::Launch launch;
    launch.args = args;
    launch.environment = environment;
    launch.timeout_s = timeout_s;
    return support::run(program, launch);
}

} // namespace window_test
