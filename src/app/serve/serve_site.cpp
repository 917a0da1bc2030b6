#include "app/serve/serve_site.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

#include <cctype>

#include "app/serve/request_path.hpp"
#include "app/serve/tile_answers.hpp"
#include "track/io/text_output.hpp"

namespace trailray::app::serve {
namespace {

// Files that may change while the server runs (the app rebuilt, a track rewritten): the browser
// asks again each time.
constexpr const char* kRevalidate = "no-cache";

std::string percent_encode_segment(std::string_view text) {
  std::string out;
  for (unsigned char c : text) {
    if (std::isalnum(c) || c == '-' || c == '.' || c == '_' || c == '~')
      out += static_cast<char>(c);
    else
      out += fmt::format("%{:02X}", c);
  }
  return out;
}

// A file's whole bytes, or 404 when it is gone or not a regular file.
HttpResponse file_response(const std::string& path, std::string_view content_type) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return text_response(404, "not found");
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    return text_response(404, "not found");
  }
  HttpResponse r;
  r.content_type = std::string(content_type);
  r.file = fd;
  r.file_size = static_cast<std::uint64_t>(st.st_size);
  r.headers.emplace_back("Cache-Control", kRevalidate);
  r.headers.emplace_back("X-Content-Type-Options", "nosniff");
  return r;
}

HttpResponse static_file_response(const std::filesystem::path& file) {
  // No cross-origin isolation (COOP/COEP): the page has no threads to gain from it, and it would
  // block tiles from servers that send no CORP header.
  return file_response(file.string(), content_type_for(file));
}

// `/` where the web root has no index.html: the server still works (tracks, tiles); the page says
// how to build the app.
HttpResponse not_built_page(const ServeSite& site) {
  std::string tracks;
  for (std::size_t i = 0; i < site.tracks.size(); ++i)
    tracks += fmt::format("<li><a href=\"{}\">{}</a></li>\n", track::xml_escape(track_url(i, site.tracks[i].name)),
                          track::xml_escape(site.tracks[i].name));
  HttpResponse r;
  r.content_type = "text/html; charset=utf-8";
  r.headers.emplace_back("Cache-Control", kRevalidate);
  r.body = fmt::format(
      "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>trailray serve</title></head><body>\n"
      "<h1>trailray serve</h1>\n"
      "<p>The web app is not built: there is no index.html in <code>{}</code>.</p>\n"
      "<p>Build it with <code>scripts/web.sh</code> in trailray's source folder, or give its folder with "
      "<code>--web-root DIR</code>, then reload this page.</p>\n"
      "<p>Configuration: <a href=\"/api/config.json\">/api/config.json</a></p>\n"
      "<h2>Tracks</h2>\n{}\n</body></html>\n",
      track::xml_escape(site.web_root.path().string()),
      tracks.empty() ? std::string("<p>None given.</p>") : "<ul>\n" + tracks + "</ul>");
  return r;
}

HttpAnswer now(HttpResponse r) {
  HttpAnswer a;
  a.now = std::move(r);
  return a;
}

HttpAnswer not_found() { return now(text_response(404, "not found")); }

HttpAnswer tile_answer(const ServeSite& site, const RequestPath& path) {
  const auto& s = path.segments;
  if (s.size() < 2 || path.trailing_slash) return not_found();
  if (s[1] == "terrain" && site.heights != nullptr) {
    const auto tile = parse_tile_segments(s, 2, ".png", site.terrain_max_zoom);
    if (!tile) return not_found();
    terrain::HeightSource* source = site.heights;
    return {std::nullopt,
            [source, id = *tile](std::stop_token stop) { return terrain_tile_response(*source, id, stop); }};
  }
  if (s[1] == "imagery" && site.imagery != nullptr) {
    const auto tile = parse_tile_segments(s, 2, "", site.imagery_max_zoom);
    if (!tile) return not_found();
    terrain::ImagerySource* source = site.imagery;
    return {std::nullopt,
            [source, id = *tile](std::stop_token stop) { return imagery_tile_response(*source, id, stop); }};
  }
  return not_found();
}

}  // namespace

std::string track_url(std::size_t index, const std::string& name) {
  return fmt::format("/tracks/{}/{}", index, percent_encode_segment(name));
}

bool is_loopback_host(std::string_view host) {
  std::string_view name = host;
  if (name.starts_with('[')) {
    const std::size_t close = name.find(']');
    if (close == std::string_view::npos) return false;
    name = name.substr(1, close - 1);
    return name == "::1";
  }
  if (const std::size_t colon = name.find(':'); colon != std::string_view::npos) name = name.substr(0, colon);
  std::string lower(name);
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (lower == "localhost") return true;
  return is_loopback_address(lower) && lower.find_first_not_of("0123456789.") == std::string::npos;
}

HttpAnswer answer_request(const ServeSite& site, const HttpRequest& request) {
  if (request.method != "GET" && request.method != "HEAD") {
    HttpResponse r = text_response(405, "only GET and HEAD: this server is read-only");
    r.headers.emplace_back("Allow", "GET, HEAD");
    return now(std::move(r));
  }
  const ParsedTarget target = parse_request_target(request.target);
  if (!target.ok()) return now(text_response(400, "bad request: " + target.error));
  if (site.loopback_hosts_only && !request.host.empty() && !is_loopback_host(request.host))
    return now(text_response(403, "this server answers only to 127.0.0.1 and localhost"));

  const RequestPath& path = target.path;
  const auto& s = path.segments;
  if (!s.empty() && s[0] == "api") {
    if (s.size() >= 2 && s[1] == "photos") {
      const auto photo = parse_photo_path(path, site.photos.size());
      if (!photo) return not_found();
      const ServedPhoto& p = site.photos[photo->index];  // the site outlives its server's jobs
      if (!photo->large) return now(photo_thumbnail_response(p));
      return {std::nullopt, [&p](std::stop_token stop) { return large_photo_response(p, stop); }};
    }
    if (s.size() != 2 || s[1] != "config.json" || path.trailing_slash) return not_found();
    HttpResponse r;
    r.content_type = "application/json";
    r.body = site.config_json;
    r.headers.emplace_back("Cache-Control", kRevalidate);
    return now(std::move(r));
  }
  if (!s.empty() && s[0] == "tracks") {
    if (s.size() != 3 || path.trailing_slash) return not_found();
    const auto index = parse_segment_number(s[1]);
    if (!index || *index >= site.tracks.size() || site.tracks[*index].name != s[2]) return not_found();
    return now(file_response(site.tracks[*index].path, "application/octet-stream"));
  }
  if (!s.empty() && s[0] == "tiles") return tile_answer(site, path);

  if (const auto file = site.web_root.resolve(path)) return now(static_file_response(*file));
  if (s.empty()) return now(not_built_page(site));
  return not_found();
}

}  // namespace trailray::app::serve
