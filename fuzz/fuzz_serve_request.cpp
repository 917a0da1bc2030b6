// libFuzzer target for what `trailray serve` reads from the network before any file is touched:
// the request target (parse_request_target), a path segment as a number (parse_segment_number),
// and the web root's answer to a parsed path (WebRoot::resolve, over a scratch root holding a
// page, a hidden file, a folder and links that point out of it). Each must answer or refuse,
// never crash, and what it accepts must be sane:
//   a parsed path's segments are names: non-empty, no '/', '\', NUL or control byte, not . or ..
//   a number parses only in its one spelling (its decimal text is the segment)
//   a resolved file is a regular file inside the root, reached through no hidden name
//   a photo's path (parse_photo_path) names one of the photos served, never one past them

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "app/serve/request_path.hpp"
#include "app/serve/web_root.hpp"

namespace {

using namespace trailray::app::serve;
namespace fs = std::filesystem;

void check(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "fuzz: contract violated: %s\n", what);
    std::abort();
  }
}

// <tmp>/trailray-fuzz-serve-PID/{web/{index.html, app.js, .secret, sub/index.html, out -> .., etc -> /etc}, private.txt}
const fs::path& scratch() {
  static const fs::path folder = [] {
    const fs::path f = fs::temp_directory_path() / ("trailray-fuzz-serve-" + std::to_string(::getpid()));
    fs::create_directories(f / "web" / "sub");
    for (const char* name : {"web/index.html", "web/app.js", "web/.secret", "web/sub/index.html", "private.txt"})
      std::ofstream(f / name) << name;
    std::error_code ec;
    fs::create_directory_symlink("..", f / "web" / "out", ec);
    fs::create_directory_symlink("/etc", f / "web" / "etc", ec);
    std::atexit([] {
      std::error_code ignored;
      fs::remove_all(fs::temp_directory_path() / ("trailray-fuzz-serve-" + std::to_string(::getpid())), ignored);
    });
    return f;
  }();
  return folder;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);

  if (const auto number = parse_segment_number(text)) check(std::to_string(*number) == text, "a number's one spelling");

  const ParsedTarget parsed = parse_request_target(text);
  if (!parsed.ok()) return 0;
  for (const std::string& segment : parsed.path.segments) {
    check(!segment.empty() && segment != "." && segment != "..", "a segment is a name");
    for (const char c : segment) {
      const auto byte = static_cast<unsigned char>(c);
      check(c != '/' && c != '\\' && byte >= 0x20 && byte != 0x7f, "no separator or control byte in a segment");
    }
  }

  // Three photos served: an index at or past them is no photo (a 404, never a read out of bounds).
  if (const auto photo = parse_photo_path(parsed.path, 3)) {
    check(photo->index < 3, "a photo's index names a photo served");
    check(parsed.path.segments.size() == (photo->large ? 4u : 3u), "a photo's path has its one shape");
  }

  static const WebRoot root(scratch() / "web");
  if (const auto file = root.resolve(parsed.path)) {
    const fs::path base = fs::canonical(scratch() / "web");
    const fs::path relative = file->lexically_relative(base);
    check(!relative.empty() && *relative.begin() != "..", "the file lies inside the root");
    for (const fs::path& part : relative) check(part.string().front() != '.', "no hidden name on the way");
    check(fs::is_regular_file(*file), "a regular file");
  }
  return 0;
}
