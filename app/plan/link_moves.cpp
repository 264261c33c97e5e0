#include "plan/link_moves.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

namespace plan {
namespace {

void move_frame(frustum::Frame<float>& frame, const LinkMove& move, const glm::vec3& centre) {
    const glm::mat3 turn = glm::mat3(glm::rotate(glm::mat4(1.0f), move.turn_rad, glm::vec3(0.0f, 1.0f, 0.0f)));
    frame.origin = centre + turn * (frame.origin - centre);
    frame.x = turn * frame.x;
    frame.y = turn * frame.y;
}

} // namespace

void move_links(std::vector<ViewLink>& links, const std::vector<LinkMove>& moves) {
    for (std::size_t i = 0; i < std::min(links.size(), moves.size()); ++i) {
        ViewLink& link = links[i];
        const LinkMove& move = moves[i];
        link.entry.origin += move.push_m * link.entry.normal();
        const glm::vec3 centre = link.entry.origin;
        move_frame(link.entry, move, centre);
        if (link.kind == ViewLink::Kind::Portal) {
            move_frame(link.exit, move, centre);
        }
    }
}

} // namespace plan
