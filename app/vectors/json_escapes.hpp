// The JSON escapes "\X" of one character each, shared by the reader (which
// also takes "\/" and "\uXXXX") and the writer (which writes other control
// characters as "\u00XX").
#pragma once

namespace vectors {

struct JsonEscape {
    char letter;    // after the backslash
    char character; // what it stands for
};

inline constexpr JsonEscape kJsonEscapes[] = {{'"', '"'},  {'\\', '\\'}, {'b', '\b'}, {'f', '\f'},
                                              {'n', '\n'}, {'r', '\r'},  {'t', '\t'}};

} // namespace vectors
