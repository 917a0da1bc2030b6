#pragma once
// NumPy arrays over track points. A TrackPoint array is the reader's own memory (64 bytes per
// point), so one field of it is a strided view: no copy, however large the track. Where the
// points lie in several pieces (a track of several segments) the field is copied once into one
// array, which is kept: later accesses hand out the same array. Every array is read-only, since
// the tracks it views are shared by the File and every Track taken from it.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "track/model.hpp"

namespace trailray::python {

namespace py = pybind11;

// The recorded channels a track may carry, by the names Python sees.
struct ChannelField {
  const char* name;
  float track::TrackPoint::*member;
};
const std::vector<ChannelField>& channel_fields();

class PointArrays {
 public:
  // `owner` keeps the memory of `parts` alive for as long as any array of them lives.
  PointArrays(std::shared_ptr<const void> owner, std::vector<std::span<const track::TrackPoint>> parts);

  std::size_t size() const { return size_; }
  py::array lat() const;
  py::array lon() const;
  py::array ele() const;
  // datetime64[ms], NaT where a point has no time (computed once: seconds as doubles are not
  // NumPy's datetimes).
  py::array time() const;
  // float32, or None when no point has the channel.
  py::object channel(const std::string& name) const;
  // The names of the channels some point has, in channel_fields() order.
  std::vector<std::string> channels() const;

 private:
  template <typename T>
  py::array field(const char* key, T track::TrackPoint::*member) const;
  py::object base() const;

  std::shared_ptr<const void> owner_;
  std::vector<std::span<const track::TrackPoint>> parts_;
  std::size_t size_ = 0;
  mutable std::map<std::string, py::object> cache_;
  mutable std::optional<std::vector<std::string>> channels_;
};

}  // namespace trailray::python
