// The user's moves of the recursion effect's two facing mirrors (the
// window's keys and panel, issue 16): each mirror on its own, slid along
// its normal and turned about the world's +Y through its centre, after
// place_facing_links() put them for the frame's camera. Pure: no GL.
#pragma once

#include "plan/view_links.hpp"

#include <vector>

namespace plan {

struct LinkMove {
    float push_m = 0.0f;   // along the mirror's normal: > 0 into the corridor (towards the other one)
    float turn_rad = 0.0f; // about world +Y through the mirror's centre
    bool operator==(const LinkMove& other) const { return push_m == other.push_m && turn_rad == other.turn_rad; }
};

// Moves links[i] (its entry frame; a portal's exit too) by moves[i], for
// the first min(links, moves) links; the frames stay orthonormal.
void move_links(std::vector<ViewLink>& links, const std::vector<LinkMove>& moves);

} // namespace plan
