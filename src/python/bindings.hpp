#pragma once
// The parts of the extension module trailray._core, each bound in its own file.

#include <pybind11/pybind11.h>

namespace trailray::python {

namespace py = pybind11;

void bind_track_objects(py::module_& m);  // track_objects.cpp: File, Track, Segment
void bind_reading(py::module_& m);        // read_binding.cpp: read_file
void bind_analysis(py::module_& m);       // analysis_bindings.cpp: score, flight, task, airspace, elevation
void bind_rendering(py::module_& m);      // render_binding.cpp: render
void bind_heatmap(py::module_& m);        // heatmap_binding.cpp: HeatmapCounts, encode_count_geotiff

}  // namespace trailray::python
