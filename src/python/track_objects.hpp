#pragma once
// What `trailray.read` gives Python: the File as read, its Tracks (routes too, as one-segment
// tracks) and their Segments. They share one immutable FileData, so the arrays a Track hands out
// stay valid while any of them lives, and nothing is copied to take a track out of its file.

#include <pybind11/pybind11.h>

#include <memory>
#include <string>
#include <vector>

#include "python/point_arrays.hpp"
#include "track/diagnostics.hpp"
#include "track/model.hpp"

namespace trailray::python {

struct FileData {
  std::string path;  // as given; "<bytes>" for bytes
  track::TrackFile file;
  std::vector<track::Track> routes;  // the file's routes as tracks of one segment (moved, not copied)
  std::vector<std::string> warnings;  // "file:line:column: message"
  // Which IGC altitude became the elevation (airspace checks compare FL limits accordingly).
  track::ReadOptions::IgcAltitude igc_altitude = track::ReadOptions::IgcAltitude::Auto;
};

// Moves the file's routes into FileData::routes.
std::shared_ptr<const FileData> make_file_data(std::string path, track::TrackFile file,
                                               std::vector<std::string> warnings,
                                               track::ReadOptions::IgcAltitude igc_altitude);

class Segment {
 public:
  Segment(std::shared_ptr<const FileData> owner, const track::Segment& segment);
  const PointArrays& points() const { return arrays_; }

 private:
  PointArrays arrays_;
};

class Track {
 public:
  // `track` lies in `owner` (a track or a route of it).
  Track(std::shared_ptr<const FileData> owner, const track::Track& track, bool is_route);

  const track::Track& model() const { return *track_; }
  const std::shared_ptr<const FileData>& owner() const { return owner_; }
  bool is_route() const { return is_route_; }
  const PointArrays& points() const { return arrays_; }
  std::vector<Segment> segments() const;
  py::list segment_list() const;  // made once, as File::track_list
  // Its position among the file's tracks (or routes).
  std::size_t index() const;
  // A file holding this track alone (a copy), as the reports that take a file want it.
  track::TrackFile as_file() const;

 private:
  std::shared_ptr<const FileData> owner_;
  const track::Track* track_;
  bool is_route_;
  PointArrays arrays_;
  mutable py::object segments_;
};

class File {
 public:
  explicit File(std::shared_ptr<const FileData> data) : data_(std::move(data)) {}
  const FileData& data() const { return *data_; }
  std::vector<Track> tracks() const;
  std::vector<Track> routes() const;
  // The Track objects Python sees, made once: a track's arrays are joined once per Track object,
  // so f.tracks[0].lat twice must reach the same object. A fresh list of them each time.
  py::list track_list() const;
  py::list route_list() const;

 private:
  std::shared_ptr<const FileData> data_;
  mutable py::object tracks_, routes_;  // tuples, once made
};

void bind_track_objects(py::module_& m);

}  // namespace trailray::python
