// Error text from tinygltf or nlohmann, made fit for our one-line messages.
#pragma once

#include <string>

namespace scene::detail {

// Joins lines with "; ", trims trailing space, and clips every run of more
// than 80 non-space characters (base64 data uris, mostly) to its first 60
// characters followed by "...(N bytes)".
std::string foreign_message(const std::string& text);

} // namespace scene::detail
