// trailray._core.HeatmapCounts: track/heatmap's sparse counts for Python and Dask. Files are read
// and counted without the GIL; the counts travel between processes as their non-empty tiles
// (pickle), and add up exactly (merge).

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cstring>
#include <string>

#include "app/pictures/heatmap_output.hpp"
#include "python/bindings.hpp"
#include "python/text.hpp"
#include "python/track_objects.hpp"
#include "terrain/writers/count_geotiff.hpp"
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
      for (const track::Track& t : r.file.tracks) counts.add_track(t);  // by the counts' measure
  }
  return error ? py::object(text(*error)) : py::object(py::none());
}

HeatmapWindow window_of(const py::tuple& w) {
  return {w[0].cast<std::int64_t>(), w[1].cast<std::int64_t>(), w[2].cast<std::int64_t>(), w[3].cast<std::int64_t>()};
}

py::tuple window_tuple(const HeatmapWindow& w) { return py::make_tuple(w.col0, w.row0, w.col1, w.row1); }

track::HeatmapMeasure measure_of(const std::string& of) {
  const auto m = track::parse_heatmap_measure(of);
  if (!m) throw py::value_error("of='" + of + "': heatmaps count tracks, thermals or time");
  return *m;
}

// (cell, tracks, [(tile col, tile row, bytes)], measure): what pickle carries.
py::tuple state_of(const HeatmapCounts& c) {
  py::list tiles;
  for (const auto& [key, counts] : c.tiles())
    tiles.append(py::make_tuple(key.first, key.second,
                                py::bytes(reinterpret_cast<const char*>(counts.data()), sizeof(counts))));
  return py::make_tuple(c.cell_m(), c.tracks(), tiles, std::string(track::heatmap_measure_name(c.measure())));
}

HeatmapCounts from_state(const py::tuple& state) {
  HeatmapCounts c(state[0].cast<double>(), measure_of(state[3].cast<std::string>()));
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
      .def(py::init([](double cell, const std::string& of) { return HeatmapCounts(cell, measure_of(of)); }),
           py::arg("cell"), py::arg("of") = "tracks")
      .def_property_readonly("cell", &HeatmapCounts::cell_m)
      .def_property_readonly("of",
                             [](const HeatmapCounts& c) { return std::string(track::heatmap_measure_name(c.measure())); })
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
      .def("cropped", [](const HeatmapCounts& c, const py::tuple& w) { return c.cropped(window_of(w)); })
      .def(
          "write_tiles",
          [](const HeatmapCounts& c, const std::string& path, int min_zoom, std::optional<int> max_zoom,
             const std::string& colormap, const std::string& scale) {
            app::HeatmapTileOptions options;
            options.min_zoom = min_zoom;
            options.max_zoom = max_zoom;
            const auto map = scene::parse_colormap(colormap);
            if (!map) throw py::value_error("colormap='" + colormap + "' is not a colormap");
            const auto s = scene::parse_heatmap_scale(scale);
            if (!s) throw py::value_error("scale='" + scale + "': log or linear");
            options.palette.colormap = *map;
            options.palette.scale = *s;
            app::HeatmapOutputKind kind;
            try {
              kind = app::heatmap_output_kind(path);
            } catch (const std::invalid_argument& e) {
              throw py::value_error(e.what());
            }
            if (kind == app::HeatmapOutputKind::geotiff) throw py::value_error("write_tiles writes .mbtiles or folders");
            py::gil_scoped_release unlocked;
            const app::HeatmapWritten w = app::write_heatmap_tiles(c, path, kind, options, true);
            return w.tiles;
          },
          py::arg("path"), py::arg("min_zoom") = 0, py::arg("max_zoom") = py::none(), py::arg("colormap") = "warm",
          py::arg("scale") = "log")
      .def(py::pickle([](const HeatmapCounts& c) { return state_of(c); },
                      [](const py::tuple& state) { return from_state(state); }));
  m.def(
      "read_heatmap_counts",
      [](const std::string& path) {
        py::gil_scoped_release unlocked;
        return app::read_heatmap_counts(path);
      },
      py::arg("path"));
  m.def(
      "encode_count_geotiff",
      [](const py::array_t<std::uint32_t, py::array::c_style | py::array::forcecast>& counts,
         const std::array<double, 6>& geotransform, const std::string& what) {
        if (counts.ndim() != 2) throw py::value_error("counts must be a 2-D array");
        std::vector<unsigned char> tiff;
        {
          py::gil_scoped_release unlocked;
          tiff = terrain::encode_count_geotiff(
              std::span<const std::uint32_t>(counts.data(), static_cast<std::size_t>(counts.size())),
              static_cast<std::uint32_t>(counts.shape(1)), static_cast<std::uint32_t>(counts.shape(0)), geotransform,
              what);
        }
        return py::bytes(reinterpret_cast<const char*>(tiff.data()), tiff.size());
      },
      py::arg("counts"), py::arg("geotransform"), py::arg("what") = "tracks");
}

}  // namespace trailray::python
