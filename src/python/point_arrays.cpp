#include "python/point_arrays.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace trailray::python {

const std::vector<ChannelField>& channel_fields() {
  static const std::vector<ChannelField> fields = {
      {"hr", &track::TrackPoint::heart_rate},
      {"cadence", &track::TrackPoint::cadence},
      {"power", &track::TrackPoint::power},
      {"temperature", &track::TrackPoint::temperature},
      {"recorded_speed", &track::TrackPoint::speed},
      {"gnss_alt", &track::TrackPoint::gnss_altitude},
      {"pressure_alt", &track::TrackPoint::pressure_altitude},
  };
  return fields;
}

PointArrays::PointArrays(std::shared_ptr<const void> owner, std::vector<std::span<const track::TrackPoint>> parts)
    : owner_(std::move(owner)) {
  for (const auto& p : parts)
    if (!p.empty()) parts_.push_back(p);
  for (const auto& p : parts_) size_ += p.size();
}

namespace {

void make_read_only(py::array& a) { a.attr("flags").attr("writeable") = false; }

}  // namespace

py::object PointArrays::base() const {
  auto found = cache_.find("");
  if (found != cache_.end()) return found->second;
  // A capsule owning one more reference to the file: NumPy keeps it as the views' base.
  auto* keep = new std::shared_ptr<const void>(owner_);
  py::capsule capsule(keep, [](void* p) { delete static_cast<std::shared_ptr<const void>*>(p); });
  cache_.emplace("", capsule);
  return capsule;
}

template <typename T>
py::array PointArrays::field(const char* key, T track::TrackPoint::*member) const {
  auto found = cache_.find(key);
  if (found != cache_.end()) return found->second.cast<py::array>();
  py::array out;
  if (parts_.size() == 1) {
    const track::TrackPoint& first = parts_.front().front();
    out = py::array(py::dtype::of<T>(), {parts_.front().size()}, {sizeof(track::TrackPoint)}, &(first.*member),
                    base());
  } else {
    py::array_t<T> copy(static_cast<py::ssize_t>(size_));
    T* to = copy.mutable_data();
    for (const auto& part : parts_)
      for (const track::TrackPoint& p : part) *to++ = p.*member;
    out = std::move(copy);
  }
  make_read_only(out);
  cache_.emplace(key, out);
  return out;
}

py::array PointArrays::lat() const { return field("lat", &track::TrackPoint::lat); }
py::array PointArrays::lon() const { return field("lon", &track::TrackPoint::lon); }
py::array PointArrays::ele() const { return field("ele", &track::TrackPoint::ele); }

py::array PointArrays::time() const {
  auto found = cache_.find("time");
  if (found != cache_.end()) return found->second.cast<py::array>();
  py::array out(py::dtype("datetime64[ms]"), {size_}, {});
  auto* ms = static_cast<std::int64_t*>(out.mutable_data());
  constexpr std::int64_t kNaT = std::numeric_limits<std::int64_t>::min();
  for (const auto& part : parts_)
    for (const track::TrackPoint& p : part) {
      const double v = p.time * 1000.0;
      // Beyond what int64 milliseconds hold (no reader makes such times): no time, as NaN is.
      *ms++ = std::isfinite(v) && std::fabs(v) < 9.0e18 ? static_cast<std::int64_t>(std::llround(v)) : kNaT;
    }
  make_read_only(out);
  cache_.emplace("time", out);
  return out;
}

std::vector<std::string> PointArrays::channels() const {
  if (!channels_) {
    channels_.emplace();
    for (const ChannelField& f : channel_fields()) {
      bool present = false;
      for (const auto& part : parts_) {
        for (const track::TrackPoint& p : part)
          if (!std::isnan(p.*f.member)) {
            present = true;
            break;
          }
        if (present) break;
      }
      if (present) channels_->push_back(f.name);
    }
  }
  return *channels_;
}

py::object PointArrays::channel(const std::string& name) const {
  for (const ChannelField& f : channel_fields()) {
    if (name != f.name) continue;
    const std::vector<std::string> present = channels();
    if (std::find(present.begin(), present.end(), name) == present.end()) return py::none();
    return field(f.name, f.member);
  }
  throw py::key_error("no channel '" + name + "'");
}

}  // namespace trailray::python
