// The key list: the help overlay's text (H) and the table in
// docs/window.md (a test keeps the two in step). Pure.
#pragma once

#include "window/controls.hpp"

#include <string>
#include <vector>

namespace window {

// One binding: its keys and what they do.
struct KeyHelp {
    std::string keys;
    std::string action;
};

// Every binding, in the order shown; the effect keys list plan::kAllEffects.
std::vector<KeyHelp> key_help();

// The help overlay: a status line (effect, tiles, mirror camera, lens
// power, camera), a blank line, then one "keys\taction" line per key_help()
// entry (the tab starts the second column).
std::vector<std::string> help_lines(const ViewerState& state);

// The state the keys change, one "name=value" field per setting a key
// names, space-separated, in key_help()'s order: effect, orbit (yaw,pitch
// in degrees), pan (the orbit's target), zoom (its distance; the three
// "scene" while the scene's camera is used), mirror.turn, mirror.tilt
// (degrees), mirror.slide, mirror.push (m), mirror-camera, tiles,
// lens-power, depth, left.push, right.push (m), left.turn, right.turn
// (degrees), inset, panel, help. What FRUSTUM_WINDOW_STATE writes
// (docs/testing.md) so that tests read back what a key or a click changed.
std::string state_line(const ViewerState& state);

} // namespace window
