#include "app/serve/web_root.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <string>
#include <utility>

namespace trailray::app::serve {
namespace fs = std::filesystem;

WebRoot::WebRoot(const fs::path& root) : root_(root) {
  std::error_code ec;
  const fs::path canonical = fs::canonical(root, ec);
  if (!ec && fs::is_directory(canonical, ec)) {
    root_ = canonical;
    exists_ = true;
  }
}

bool WebRoot::has_index() const { return resolve(RequestPath{}).has_value(); }

bool WebRoot::inside(const fs::path& canonical) const {
  // Component by component: /srv/web-secret is not inside /srv/web.
  auto [root_end, path_end] = std::mismatch(root_.begin(), root_.end(), canonical.begin(), canonical.end());
  return root_end == root_.end();
}

std::optional<fs::path> WebRoot::resolve(const RequestPath& request) const {
  if (!exists_) return std::nullopt;
  fs::path wanted = root_;
  for (const std::string& segment : request.segments) {
    if (segment.empty() || segment.front() == '.') return std::nullopt;
    wanted /= segment;
  }
  std::error_code ec;
  fs::path found = fs::canonical(wanted, ec);
  if (ec || !inside(found)) return std::nullopt;
  if (fs::is_directory(found, ec)) {
    found = fs::canonical(found / "index.html", ec);
    if (ec || !inside(found)) return std::nullopt;
  } else if (request.trailing_slash) {
    return std::nullopt;  // "/app.js/" names no file
  }
  if (!fs::is_regular_file(found, ec)) return std::nullopt;
  return found;
}

std::string_view content_type_for(const fs::path& file) {
  static constexpr std::array<std::pair<std::string_view, std::string_view>, 14> kTypes{{
      {".html", "text/html; charset=utf-8"},
      {".htm", "text/html; charset=utf-8"},
      {".js", "text/javascript; charset=utf-8"},
      {".mjs", "text/javascript; charset=utf-8"},
      {".wasm", "application/wasm"},
      {".css", "text/css; charset=utf-8"},
      {".json", "application/json"},
      {".map", "application/json"},
      {".png", "image/png"},
      {".jpg", "image/jpeg"},
      {".webp", "image/webp"},
      {".svg", "image/svg+xml"},
      {".ico", "image/x-icon"},
      {".txt", "text/plain; charset=utf-8"},
  }};
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (const auto& [e, type] : kTypes)
    if (e == ext) return type;
  return "application/octet-stream";
}

}  // namespace trailray::app::serve
