#pragma once
// `stats --photos`: the photos read once for all files, placed on each file's cleaned tracks (the
// tracks whose distances the table reports), as JSON and as lines under the file's table; and
// the photos no file placed, each one warning at the end.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/diagnostics.hpp"
#include "track/photos/photo_placement.hpp"

namespace trailray::app {

struct StatsPhotos {
  std::vector<track::PhotoMetadata> photos;
  track::PhotoPlacementOptions options;
};

// "photos": [{"path", "lat", "lon", "ele", "time", "placed_by", "track", "distance_m", "gps_offset_m"}]
// of the photos placed on the file's tracks; numbers that are not known are null.
nlohmann::json placed_photos_json(const track::PhotoPlacement& placement);

// "  photos: 2 of 5 placed on this file's tracks" and a line per placed photo; `track_names`
// the file's tracks' names as the table shows them.
std::string placed_photos_lines(const track::PhotoPlacement& placement, std::size_t photo_count,
                                const std::vector<std::string>& track_names);

// The photos that no file placed, gathered file by file: each is one warning at the end, with
// the reason its placement gave (the same for every file, or that of the only file), else that
// no file's tracks hold it.
class UnplacedPhotos {
 public:
  explicit UnplacedPhotos(std::size_t photo_count) : placed_(photo_count, false), reasons_(photo_count) {}
  void add_file(const track::PhotoPlacement& placement);
  void report(const std::vector<track::PhotoMetadata>& photos, scene::Diagnostics& diagnostics) const;

 private:
  std::vector<bool> placed_;
  std::vector<std::optional<std::string>> reasons_;
  std::vector<bool> differ_ = std::vector<bool>(placed_.size(), false);
  std::size_t files_ = 0;
};

}  // namespace trailray::app
