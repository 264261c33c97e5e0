// The "room" layout of bench_recursion (docs/performance.md "Portals and
// recursive mirrors"): the classic case where recursion matters. A closed
// room 6 m wide (x), 10 m deep (z), 3 m high, tiled floor, walls, ceiling
// and a grid of boxes; two facing mirrors on the side walls (x = -3 facing
// +x, x = +3 facing -x), 3 m wide and 1.8 m high. The camera stands near the
// +x mirror looking into the -x one, yawed so the nested reflections recede
// to one side: it sees one mirror, that mirror shows the other, and so on
// (one chain of views, level k through k mirrors). Every reflected view has
// the room over its whole viewport.
#pragma once

#include <frustum/matrix_pair.hpp>
#include <plan/view_links.hpp>
#include <scene/scene.hpp>

#include <vector>

namespace bench_recursion {

struct Room {
    scene::Scene scene;                 // the room and its furniture (no mirrors: they are the links)
    std::vector<plan::ViewLink> links; // the two mirrors (plan::link_scene() draws them)
    frustum::MatrixPair<float> camera;  // at width_px x height_px
};

Room make_room(int width_px, int height_px);

} // namespace bench_recursion
