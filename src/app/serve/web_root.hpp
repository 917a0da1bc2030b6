#pragma once
// The web app's files as `trailray serve` hands them out: a request path becomes a file only when
// the file, once every link is resolved, lies inside the root (a link out of it, or a name made
// to climb, finds nothing) and no segment is hidden (`.git`, `.env`).

#include <filesystem>
#include <optional>
#include <string_view>

#include "app/serve/request_path.hpp"

namespace trailray::app::serve {

class WebRoot {
 public:
  // `root` need not exist (then nothing is found and has_index() is false).
  explicit WebRoot(const std::filesystem::path& root);

  const std::filesystem::path& path() const { return root_; }
  bool has_index() const;

  // The regular file `request` names, its canonical path; a folder stands for its index.html.
  std::optional<std::filesystem::path> resolve(const RequestPath& request) const;

 private:
  bool inside(const std::filesystem::path& canonical) const;

  std::filesystem::path root_;  // canonical when it exists
  bool exists_ = false;
};

// The Content-Type for a file's extension (application/octet-stream for unknown ones).
std::string_view content_type_for(const std::filesystem::path& file);

}  // namespace trailray::app::serve
