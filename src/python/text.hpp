#pragma once
// Text from track files as Python str. Files carry names and messages in any bytes (a Latin-1
// pilot in an IGC header, a file cut inside a character): invalid UTF-8 becomes U+FFFD here,
// where pybind11's own conversion would raise UnicodeDecodeError at the caller.

#include <pybind11/pybind11.h>

#include <string>
#include <string_view>
#include <vector>

namespace trailray::python {

namespace py = pybind11;

inline py::str text(std::string_view s) {
  PyObject* o = PyUnicode_DecodeUTF8(s.data(), static_cast<Py_ssize_t>(s.size()), "replace");
  if (o == nullptr) throw py::error_already_set();
  return py::reinterpret_steal<py::str>(o);
}

inline py::list texts(const std::vector<std::string>& lines) {
  py::list out;
  for (const std::string& s : lines) out.append(text(s));
  return out;
}

}  // namespace trailray::python
