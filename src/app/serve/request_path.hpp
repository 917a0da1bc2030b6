#pragma once
// The target of a request as `trailray serve` reads it: the raw request-target (never the one a
// library decoded for us, which turns %00 into an end of string and %2f into a separator) checked
// and percent-decoded strictly, then cut into path segments. Anything a file system could read as
// another place is refused here, before any path is built: `.` and `..` segments (also as
// %2e%2e), empty segments (`//`), backslashes, encoded slashes, NUL and other control bytes, and
// targets that are not a path from the root (`*`, `http://host/...`).

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace trailray::app::serve {

struct RequestPath {
  std::vector<std::string> segments;  // decoded; "/" has none
  bool trailing_slash = false;        // "/a/b/": a folder asked for
};

struct ParsedTarget {
  RequestPath path;
  std::string error;  // empty: path is valid; else why the target is refused (for a 400 answer)
  bool ok() const { return error.empty(); }
};

// The query (`?...`) and a fragment are ignored; the path before them must start with `/`.
ParsedTarget parse_request_target(std::string_view target);

// A path segment that names a number (a track's index, a tile's z, x or y): decimal digits in
// their one spelling (no sign, no leading zero, no spaces) of at most 2^32 - 1; else nullopt, so
// "01" or "+1" can never name what "1" names.
std::optional<std::uint32_t> parse_segment_number(std::string_view segment);

// A photo's picture asked for: "/api/photos/<N>.jpg" its thumbnail, "/api/photos/<N>/large.jpg"
// the larger one the page shows when its pin is clicked. nullopt for any other path, and for an
// index N that is not below `count` (the photos served), so a request names only what exists.
struct PhotoRequest {
  std::uint32_t index = 0;
  bool large = false;
};
std::optional<PhotoRequest> parse_photo_path(const RequestPath& path, std::size_t count);

}  // namespace trailray::app::serve
