// Helpers of the robustness suite, beside tests/support's temp folders,
// child-process runner and case-table loop: folder listings and work run
// in a forked child.
#pragma once

#include "support/case_table.hpp"
#include "support/child_process.hpp"
#include "support/temp_dir.hpp"

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rob {

// Names of the entries of a folder (empty when it does not exist).
std::vector<std::string> list_dir(const std::filesystem::path& dir);

// `work` run in a forked child (support::run_function), so that a crash, a
// sanitizer abort or a hang (the child's group killed after timeout_s, a
// failure naming the limit) fails one case instead of the whole suite. The
// child must not use doctest: it only computes the text it returns.
struct Isolated {
    bool finished = false; // the child returned normally
    std::string how;       // otherwise "killed by signal N" / "exit status N"
    std::string value;     // what work() returned
};
Isolated isolated(const std::function<std::string()>& work, unsigned timeout_s = 60);

// Runs `program` (support::run) and CHECKs, its stderr captured, that no
// signal ended it, that it exited with `exit_status` and, when `no_stdout`,
// that it wrote nothing on stdout: the first checks of every CLI case row.
support::Outcome run_checked(const std::string& program, const support::Launch& launch, int exit_status,
                             bool no_stdout);
// The same for a launch of `args` and `stdin_text`, the rest by default.
support::Outcome run_checked(const std::string& program, const std::vector<std::string>& args, int exit_status,
                             bool no_stdout, const std::string& stdin_text = "");

// True (after recording a skip) when this machine has no offscreen GL
// context, asked in-process the way frustum-demo asks (EGL, else OSMesa)
// before a run, so that the run's own errors are never mistaken for it.
bool no_gl();

} // namespace rob
