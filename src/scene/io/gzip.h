// gzip-compressed files (scanned models are often shipped as .ply.gz), through zlib.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace penumbra {

bool isGzip(std::string_view bytes);  // starts with the gzip magic number

// Inflates a gzip stream (one member or several, as `cat a.gz b.gz` makes) into memory. Throws
// Error naming `name` when the data is corrupt or truncated, or would inflate to more than
// maxBytes (so a small hostile file cannot claim unbounded memory).
std::string gunzip(std::string_view bytes, std::size_t maxBytes, const std::string& name);

}  // namespace penumbra
