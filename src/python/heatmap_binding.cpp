// trailray._core.HeatmapCounts: track/heatmap's sparse counts for Python and Dask. Files are read
// and counted without the GIL; the counts travel between processes as their non-empty tiles
// (pickle), and add up exactly (merge).

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cstring>
#include <string>

#include "python/bindings.hpp"
#include "python/text.hpp"
#include "python/track_objects.hpp"
#include "terrain/count_geotiff.hpp"
#include "track/heatmap.hpp"
#include "track/io/load.hpp"

namespace trailray::python {
namespace {

using track::HeatmapCounts;
using track::HeatmapWindow;

// Reads and counts one file: None, or the error naming the file and the position.
py::object add_file(HeatmapCounts& counts, const std::string& path, bool strict) {
  track::ReadOptions options;
  options.strict = strict;
  std::optional<std::string> error;
  {
    py::gil_scoped_release unlocked;
    track::ReadResult r = track::load_track_file(path, options);
    if (r.error)
      error = r.error->to_string();
    else
      for (const track::Track& t : r.file.tracks) counts.add_track(t);
  }
  return error ? py::object(text(*error)) : py::object(py::none());
}

HeatmapWindow window_of(const py::tuple& w) {
  return {w[0].cast<std::int64_t>(), w[1].cast<std::int64_t>(), w[2].cast<std::int64_t>(), w[3].cast<std::int64_t>()};
}

py::tuple window_tuple(const HeatmapWindow& w) { return py::make_tuple(w.col0, w.row0, w.col1, w.row1); }

// (cell, tracks, [(tile col, tile row, bytes)]): what pickle carries.
py::tuple state_of(const HeatmapCounts& c) {
  py::list tiles;
  for (const auto& [key, counts] : c.tiles())
    tiles.append(py::make_tuple(key.first, key.second,
                                py::bytes(reinterpret_cast<const char*>(counts.data()), sizeof(counts))));
  return py::make_tuple(c.cell_m(), c.tracks(), tiles);
}

HeatmapCounts from_state(const py::tuple& state) {
  HeatmapCounts c(state[0].cast<double>());
  for (const py::handle& t : state[2].cast<py::list>()) {
    const auto tile = t.cast<py::tuple>();
    const std::string bytes = tile[2].cast<std::string>();
    HeatmapCounts::Tile counts;
    if (bytes.size() != sizeof(counts)) throw py::value_error("a heatmap tile of the wrong size");
    std::memcpy(counts.data(), bytes.data(), sizeof(counts));
    c.add_tile(tile[0].cast<std::int64_t>(), tile[1].cast<std::int64_t>(), counts);
  }
  c.set_tracks(state[1].cast<std::uint64_t>());
  return c;
}

}  // namespace

void bind_heatmap(py::module_& m) {
  py::class_<HeatmapCounts>(m, "HeatmapCounts", "Sparse heatmap counts (use trailray.heatmap)")
      .def(py::init<double>(), py::arg("cell"))
      .def_property_readonly("cell", &HeatmapCounts::cell_m)
      .def_property_readonly("tracks", &HeatmapCounts::tracks)
      .def("add_file", &add_file, py::arg("path"), py::arg("strict") = false)
      .def(
          "add_track", [](HeatmapCounts& c, const Track& t) { c.add_track(t.model()); }, py::arg("track"))
      .def("merge", &HeatmapCounts::merge, py::arg("other"))
      .def("extent", [](const HeatmapCounts& c) { return window_tuple(c.extent()); })
      .def("window_of", [](const HeatmapCounts& c, double s, double w, double n, double e) {
        return window_tuple(c.window_of(s, w, n, e));
      })
      .def("raster",
           [](const HeatmapCounts& c, const py::tuple& w) {
             const HeatmapWindow window = window_of(w);
             std::vector<std::uint32_t> r;
             {
               py::gil_scoped_release unlocked;
               r = c.raster(window);
             }
             py::array_t<std::uint32_t> out({window.height(), window.width()});
             std::memcpy(out.mutable_data(), r.data(), r.size() * sizeof(std::uint32_t));
             return out;
           })
      .def("geotransform", [](const HeatmapCounts& c, const py::tuple& w) { return c.geotransform(window_of(w)); })
      .def(py::pickle([](const HeatmapCounts& c) { return state_of(c); },
                      [](const py::tuple& state) { return from_state(state); }));
  m.def(
      "encode_count_geotiff",
      [](const py::array_t<std::uint32_t, py::array::c_style | py::array::forcecast>& counts,
         const std::array<double, 6>& geotransform) {
        if (counts.ndim() != 2) throw py::value_error("counts must be a 2-D array");
        std::vector<unsigned char> tiff;
        {
          py::gil_scoped_release unlocked;
          tiff = terrain::encode_count_geotiff(
              std::span<const std::uint32_t>(counts.data(), static_cast<std::size_t>(counts.size())),
              static_cast<std::uint32_t>(counts.shape(1)), static_cast<std::uint32_t>(counts.shape(0)), geotransform);
        }
        return py::bytes(reinterpret_cast<const char*>(tiff.data()), tiff.size());
      },
      py::arg("counts"), py::arg("geotransform"));
}

}  // namespace trailray::python
