// The files a browser gets over HTTP (web/: the page and the <penumbra-view> element), embedded
// into the binary at build time (cmake/EmbedWeb.cmake), so the server needs no files beside it.
#pragma once

#include <optional>
#include <string_view>

namespace penumbra::serve {

struct WebAsset {
    std::string_view body;
    std::string_view contentType;
};

// The asset at a URL path ("/" is the page, "/penumbra-view.js" the element), or nothing.
std::optional<WebAsset> findWebAsset(std::string_view path);

}  // namespace penumbra::serve
