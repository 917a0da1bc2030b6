#include "terrain/gdal/gdal_remote.hpp"

#include <cpl_conv.h>

#include <cmath>
#include <mutex>
#include <string_view>

#include "terrain/gdal/gdal_errors.hpp"
#include "terrain/sources/source_factory.hpp"
#include "terrain/sources/url_template.hpp"

namespace trailray::terrain {
namespace {

// GDAL's HTTP settings are its configuration options, process-wide (one configuration per run).
// Headers go in as GDAL_HTTP_HEADERS, their ${VAR} expanded (the values kept out of messages).
std::vector<std::string> configure_gdal_http(const SourceSettings& s, const NetworkSettings& n) {
  static std::mutex mutex;
  std::lock_guard lock(mutex);
  gdal_detail::ensure_gdal_registered();
  const auto seconds = [](double t) { return std::to_string(std::max(1L, std::lround(t))); };
  CPLSetConfigOption("GDAL_HTTP_CONNECTTIMEOUT", seconds(n.connect_timeout_s).c_str());
  CPLSetConfigOption("GDAL_HTTP_TIMEOUT", seconds(n.timeout_s).c_str());
  CPLSetConfigOption("GDAL_HTTP_MAX_RETRY", std::to_string(std::max(0, n.retries)).c_str());
  CPLSetConfigOption("GDAL_HTTP_RETRY_DELAY", "1");
  CPLSetConfigOption("GDAL_HTTP_USERAGENT", "trailray");
  // A raster is one file: no listing of its folder (an extra request per open, and servers
  // that refuse listings make GDAL wait for the refusal).
  CPLSetConfigOption("GDAL_DISABLE_READDIR_ON_OPEN", "EMPTY_DIR");
  std::vector<std::string> secrets;
  std::string headers;
  for (const auto& [name, value] : s.headers) {
    ExpandedText expanded = expand_environment(value);
    if (!expanded.error.empty()) throw SourceError(s.source + ": header " + name + ": " + expanded.error);
    headers += name + ": " + expanded.text + "\r\n";
    secrets.insert(secrets.end(), expanded.secrets.begin(), expanded.secrets.end());
  }
  CPLSetConfigOption("GDAL_HTTP_HEADERS", headers.empty() ? nullptr : headers.c_str());
  return secrets;
}

// Opens through `open`, turning GDAL's failures into messages that say what to do.
template <class Open>
auto open_remote(const SourceSettings& s, const NetworkSettings& n, Open open) {
  if (n.offline)
    throw SourceError(s.source + ": a remote raster is read over the network, and --offline is set (give a local copy " +
                      "of the file instead)");
  const std::vector<std::string> secrets = configure_gdal_http(s, n);
  try {
    return open(remote_raster_path(s.source));
  } catch (const SourceError& e) {
    std::string message = redact_secrets(e.what(), secrets);
    if (message.find("Range downloading not supported") != std::string::npos)
      message = s.source +
                ": the server does not support range requests (HTTP Range), which reading part of a remote raster "
                "needs: download the file and give its path";
    throw SourceError(message);
  }
}

}  // namespace

std::unique_ptr<GdalHeightSource> open_remote_height_source(const SourceSettings& s, const NetworkSettings& n) {
  return open_remote(s, n, [](const std::string& path) {
    GdalOptions options;
    options.read_whole_raster = false;  // the blocks a track needs, not the file
    return std::make_unique<GdalHeightSource>(path, options);
  });
}

std::unique_ptr<GdalImagerySource> open_remote_imagery_source(const SourceSettings& s, const NetworkSettings& n) {
  return open_remote(s, n, [](const std::string& path) { return std::make_unique<GdalImagerySource>(path); });
}

}  // namespace trailray::terrain
