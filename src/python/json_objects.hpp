#pragma once
// The command line's JSON documents (`stats --json`, `flight --json`, ...) as Python objects:
// dicts, lists, floats, ints, str, None. Python gets the very numbers the commands print.

#include <pybind11/pybind11.h>

#include <nlohmann/json.hpp>

#include "python/text.hpp"

namespace trailray::python {

namespace py = pybind11;

template <typename Json>
py::object to_python(const Json& j) {
  switch (j.type()) {
    case nlohmann::json::value_t::null:
    case nlohmann::json::value_t::discarded:
      return py::none();
    case nlohmann::json::value_t::boolean:
      return py::bool_(j.template get<bool>());
    case nlohmann::json::value_t::number_integer:
      return py::int_(j.template get<std::int64_t>());
    case nlohmann::json::value_t::number_unsigned:
      return py::int_(j.template get<std::uint64_t>());
    case nlohmann::json::value_t::number_float:
      return py::float_(j.template get<double>());
    case nlohmann::json::value_t::string:
      return text(j.template get_ref<const std::string&>());
    case nlohmann::json::value_t::array: {
      py::list out;
      for (const auto& v : j) out.append(to_python(v));
      return out;
    }
    case nlohmann::json::value_t::object: {
      py::dict out;
      for (auto it = j.begin(); it != j.end(); ++it) out[text(it.key())] = to_python(it.value());
      return out;
    }
    case nlohmann::json::value_t::binary:
      break;
  }
  return py::none();
}

}  // namespace trailray::python
