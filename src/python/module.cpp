// trailray._core: the C++ half of the `trailray` package (src/python/trailray/ is the other:
// the public names, keyword arguments, warnings and pandas).

#include "python/bindings.hpp"

PYBIND11_MODULE(_core, m) {
  m.doc() = "trailray's C++ core; use the trailray package, not this module";
  trailray::python::bind_track_objects(m);
  trailray::python::bind_reading(m);
  trailray::python::bind_rendering(m);
  trailray::python::bind_analysis(m);
  trailray::python::bind_heatmap(m);
}
