#pragma once
// The TRACK arguments of every command that takes several tracks, as files: a folder stands for
// the track files in it, a glob pattern for the files it matches. Shells expand globs before the
// program sees them, but a quoted pattern, a pattern too long for the command line, or a shell
// that does not expand (Windows' cmd) leaves it to us.

#include <stdexcept>
#include <string>
#include <vector>

namespace trailray::app {

// A TRACK argument that names nothing (a pattern without a match, a folder without track files).
class TrackArgumentError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Whether a file's name says it is a track file trailray reads: .gpx .igc .tcx .fit .kml .kmz
// .geojson .json, any case, each also with .gz after it.
bool has_track_extension(const std::string& name);

// Each argument in order, each becoming:
// - itself when it is `-` (standard input) or an existing file, whatever characters it holds;
// - for an existing folder: its track files (has_track_extension; not hidden: no leading dot),
//   not those of its subfolders, sorted by name (byte order);
// - for a pattern (`*`, `?`, `[...]`, `\` in a name that does not exist; `*` and `?` never match
//   `/` nor a leading dot; `**` as a whole component matches any number of folders, none
//   included, not hidden ones; `\*` is a literal `*`): the matching track files and the track
//   files of the matching folders, sorted by name (byte order);
// - anything else itself (the reader then says it cannot be opened).
// Throws TrackArgumentError naming the pattern or the folder that gives no track file.
std::vector<std::string> expand_track_arguments(const std::vector<std::string>& arguments);

// The glob match of one name (no `/`): `*` any run, `?` any one character, `[abc]` `[a-z]` `[!a]`
// `[^a]` a set, `\c` the character c itself; a leading dot only matched by a leading dot.
// Exposed for its tests.
bool glob_name_matches(const std::string& pattern, const std::string& name);

}  // namespace trailray::app
