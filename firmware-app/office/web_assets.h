#pragma once
// The office's pages (ui/web/: index.html, the JS modules, style.css)
// compiled into the binary by a build step (cmake/embed_web_assets.cmake),
// so the server is one file to install and the pages always match it.
#include <string_view>

namespace rockface::app::office_web {

struct WebAsset {
  std::string_view name;          // "index.html", "app.js", ...
  std::string_view content_type;  // "text/html; charset=utf-8", ...
  std::string_view bytes;
};

// The asset of that file name, null when there is none.
const WebAsset* find_web_asset(std::string_view name);

}  // namespace rockface::app::office_web
