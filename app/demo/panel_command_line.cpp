#include "demo/panel_command_line.hpp"

#include <algorithm>

namespace demo {

std::vector<std::pair<std::size_t, std::size_t>> PanelCommandLine::options_at() const {
    std::vector<std::pair<std::size_t, std::size_t>> at;
    for (std::size_t i = 1; i < args_.size();) {
        const Option* option = find_option(kWindow, args_[i]);
        const std::size_t span = option && option->value && i + 1 < args_.size() ? 2 : 1;
        at.emplace_back(i, span);
        i += span;
    }
    return at;
}

std::optional<std::string> PanelCommandLine::value(const std::string& name) const {
    std::optional<std::string> found;
    for (const auto& [i, span] : options_at()) {
        if (args_[i] == name) {
            found = span == 2 ? args_[i + 1] : std::string();
        }
    }
    return found;
}

void PanelCommandLine::remove(const std::string& name) {
    const auto at = options_at();
    for (auto it = at.rbegin(); it != at.rend(); ++it) {
        if (args_[it->first] == name) {
            const auto first = args_.begin() + static_cast<std::ptrdiff_t>(it->first);
            args_.erase(first, first + static_cast<std::ptrdiff_t>(it->second));
        }
    }
}

void PanelCommandLine::set(const std::string& name, const std::string& value) {
    const Option* option = find_option(kWindow, name);
    const auto at = options_at();
    const auto first = std::find_if(at.begin(), at.end(), [&](const auto& a) { return args_[a.first] == name; });
    if (first == at.end()) {
        args_.push_back(name);
        if (option && option->value) {
            args_.push_back(value);
        }
        return;
    }
    // Keep the first occurrence's place; drop the others.
    const std::size_t place = first->first;
    if (option && option->value && first->second == 2) {
        args_[place + 1] = value;
    }
    for (auto it = at.rbegin(); it != at.rend() && it->first > place; ++it) {
        if (args_[it->first] == name) {
            const auto begin = args_.begin() + static_cast<std::ptrdiff_t>(it->first);
            args_.erase(begin, begin + static_cast<std::ptrdiff_t>(it->second));
        }
    }
}

std::string PanelCommandLine::text() const {
    std::string line = "frustum-demo";
    for (const std::string& arg : args_) {
        const bool plain = !arg.empty() && arg.find_first_of(" '\"\\$") == std::string::npos;
        line += " " + (plain ? arg : "'" + arg + "'");
    }
    return line;
}

std::variant<HelpRequest, WindowRequest, Failure> PanelCommandLine::parse() const {
    return parse_window_command_line(args_);
}

} // namespace demo
