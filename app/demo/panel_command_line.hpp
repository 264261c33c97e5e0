// The command line the window's control panel edits: the window's own
// arguments, with a control's new value replacing its option's (or added,
// or a flag removed), re-parsed by parse_window_command_line() exactly as
// at start-up. So a panel value is checked by the option table's row (same
// bounds, same message) and the panel can show the command line that
// reproduces what the window shows. Pure: no GL, no ImGui.
#pragma once

#include "demo/window_command_line.hpp"

#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace demo {

class PanelCommandLine {
public:
    // args[0] is "window"; the rest parsed by parse_window_command_line().
    explicit PanelCommandLine(std::vector<std::string> args) : args_(std::move(args)) {}

    // The value of the last `name` given; "" for a flag; empty when absent.
    std::optional<std::string> value(const std::string& name) const;
    // Replaces every `name` by one `name value` (a flag: `value` ignored), else appends it.
    void set(const std::string& name, const std::string& value);
    void remove(const std::string& name);

    const std::vector<std::string>& args() const { return args_; }
    // "frustum-demo window --effect lens --lens-power 1.5"
    std::string text() const;
    // parse_window_command_line(args()).
    std::variant<HelpRequest, WindowRequest, Failure> parse() const;

private:
    // Index of each option name in args_ with how many arguments it spans (1 or 2).
    std::vector<std::pair<std::size_t, std::size_t>> options_at() const;
    std::vector<std::string> args_;
};

} // namespace demo
