// One row per pass name: what the GPU timer and the fragment counter read
// back for a frame is summed by the name given to render::RenderOptions::
// pass_end, so both stereo eyes' "main view", or every view of one
// recursion level ("level 2 (2 views)"), make one row. Rows keep the order
// in which their names first ended.
#pragma once

#include <string>
#include <vector>

namespace window {

// Adds `value` to the `field` of the row named `pass` in `rows` (a Row has a
// std::string `pass`), appending a row when there is none yet.
template <class Row, class T>
void add_to_pass(std::vector<Row>& rows, const std::string& pass, T Row::*field, T value) {
    for (Row& row : rows) {
        if (row.pass == pass) {
            row.*field += value;
            return;
        }
    }
    Row row{};
    row.pass = pass;
    row.*field = value;
    rows.push_back(std::move(row));
}

} // namespace window
