#pragma once
// --photos, --photo-tz and --photo-time-offset, spelled the same in `stats`, `render`, `view`,
// `video` and `serve`: photos (JPEG, HEIC) read with their EXIF (track/photos/exif_reader) and
// placed on the command's tracks (track/photos/photo_placement). One function reads and places
// for a set of tracks and says on the diagnostics what it could not do, photo by photo.

#include <stdexcept>
#include <string>
#include <vector>

#include "scene/diagnostics.hpp"
#include "track/model.hpp"
#include "track/photos/photo_placement.hpp"

namespace CLI {
class App;
}  // namespace CLI

namespace trailray::app {

struct PhotoArgs {
  std::vector<std::string> paths;  // --photos as given (repeatable): files and folders
  std::string time_zone;           // --photo-tz "+HH:MM" ("": none)
  double time_offset_s = 0.0;      // --photo-time-offset: added to every photo's time
  bool any() const { return !paths.empty(); }
};

// Registers the three options on `command`; --photo-tz is checked while parsing.
void add_photo_options(CLI::App& command, PhotoArgs& args);

// A --photos argument that names nothing.
class PhotoArgumentError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Whether a file's name says it is a photo: .jpg .jpeg .heic .heif, any case.
bool has_photo_extension(const std::string& name);

// Each argument in order: a file itself (whatever its name: the reader says when it is no photo),
// a folder its photo files (has_photo_extension; not hidden, not those of its subfolders) sorted
// by name. Throws PhotoArgumentError naming an argument that does not exist.
std::vector<std::string> expand_photo_arguments(const std::vector<std::string>& arguments);

// The placement's options from the arguments (the zone parsed; the hint names --photo-tz).
track::PhotoPlacementOptions photo_placement_options(const PhotoArgs& args);

// Reads each photo file, in order (exiv2's parsing is serialized: threads would gain little). A
// photo that cannot be read is a warning and is left out; the reader's warnings are passed on.
std::vector<track::PhotoMetadata> read_photo_files(const std::vector<std::string>& files, scene::Diagnostics& diagnostics);

// Everything the drawing commands need: expands args.paths, reads the photos and places them on
// `tracks` (PlacedPhoto::track indexes this vector; null entries are skipped), each photo that is
// not placed a warning saying why; a photo placed by time far from its GPS position a warning.
// Empty without --photos. Throws PhotoArgumentError for a --photos path that does not exist.
std::vector<track::PlacedPhoto> read_and_place_photos(const PhotoArgs& args, const std::vector<const track::Track*>& tracks,
                                                      scene::Diagnostics& diagnostics);

}  // namespace trailray::app
