// trailray._core.render: `trailray render`'s picture (app/pictures/render_picture) as a NumPy array. The
// keyword arguments arrive as the command's own options, parsed by the command's own definitions
// (add_render_options), so they are spelled, defaulted and checked exactly as on the command line.

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "app/common/track_arguments.hpp"
#include "app/pictures/render_picture.hpp"
#include "python/bindings.hpp"
#include "python/text.hpp"
#include "python/track_objects.hpp"

namespace trailray::python {
namespace {

// What a Python object to draw becomes: the file it was read from, whole or with one track.
scene::LoadedTrackFile loaded_file(const py::handle& object) {
  scene::LoadedTrackFile out;
  auto route_of = [](const track::Track& t) {
    track::Route r;
    r.name = t.name;
    for (const track::Segment& s : t.segments) r.points.insert(r.points.end(), s.points.begin(), s.points.end());
    return r;
  };
  if (py::isinstance<File>(object)) {
    const FileData& d = object.cast<const File&>().data();
    out.path = d.path;
    out.file = d.file;
    for (const track::Track& r : d.routes) out.file.routes.push_back(route_of(r));
    return out;
  }
  if (py::isinstance<Track>(object)) {
    const Track& t = object.cast<const Track&>();
    out.path = t.owner()->path;
    out.file.format = t.owner()->file.format;
    out.file.metadata = t.owner()->file.metadata;
    if (t.is_route())
      out.file.routes.push_back(route_of(t.model()));
    else
      out.file.tracks.push_back(t.model());
    return out;
  }
  throw py::type_error(fmt::format("render() draws Files, Tracks and paths, not {}",
                                   py::str(py::type::of(object).attr("__name__")).cast<std::string>()));
}

// Options Python may not give: the file (the picture is returned), the help, the frame timing.
const std::set<std::string>& refused_options() {
  static const std::set<std::string> refused = {"output", "help", "profile", "frames"};
  return refused;
}

// One keyword argument as the command line's words: a flag for True (or "on" for an on|off
// option), its "--no-" twin or "off" for False, "--name value" per value otherwise.
void add_words(CLI::App& app, const std::string& key, const py::handle& value, std::vector<std::string>& argv) {
  std::string name = key;
  std::replace(name.begin(), name.end(), '_', '-');
  CLI::Option* option = app.get_option_no_throw("--" + name);
  CLI::Option* negative = app.get_option_no_throw("--no-" + name);
  if ((option == nullptr && negative == nullptr) || refused_options().count(name) > 0)
    throw py::type_error(fmt::format("render() got an unexpected keyword argument '{}'", key));
  if (py::isinstance<py::bool_>(value)) {
    const bool on = value.cast<bool>();
    if (!on && negative != nullptr) {  // shadows=False, labels=False: --no-shadows, --no-labels
      argv.push_back("--no-" + name);
      return;
    }
    if (option != nullptr && option->get_expected_max() == 0) {  // a flag: snow=True
      if (on) argv.push_back("--" + name);
      return;
    }
    // Only --no-NAME exists, or NAME takes values beside its --no- twin (labels=True): the default.
    if (option == nullptr || negative != nullptr) return;
    argv.push_back("--" + name);  // an on|off option: legend=False
    argv.push_back(on ? "on" : "off");
    return;
  }
  if (option == nullptr) throw py::type_error(fmt::format("render(): {} takes True or False", key));
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    for (const py::handle& v : value) {
      argv.push_back("--" + name);
      argv.push_back(py::str(v).cast<std::string>());
    }
    return;
  }
  argv.push_back("--" + name);
  argv.push_back(py::str(value).cast<std::string>());
}

// (picture, warnings): the picture an (h, w, 4) uint8 array, sRGB, top row first.
py::tuple render(const py::list& paths, const py::list& objects, const py::dict& options) {
  auto args = std::make_shared<app::RenderArgs>();
  CLI::App command("trailray.render");
  app::add_render_options(command, *args);
  command.get_option("--output")->required(false);
  std::vector<std::string> argv;
  for (const auto& [key, value] : options)
    if (!value.is_none()) add_words(command, key.cast<std::string>(), value, argv);
  for (const py::handle& p : paths) argv.push_back(p.cast<std::string>());
  std::vector<scene::LoadedTrackFile> more;
  for (const py::handle& o : objects) more.push_back(loaded_file(o));
  std::reverse(argv.begin(), argv.end());  // CLI11 takes them last first
  try {
    command.parse(argv);
  } catch (const CLI::ParseError& e) {
    throw py::value_error(fmt::format("render(): {}", e.what()));
  }

  scene::CollectedDiagnostics diagnostics;
  auto image = std::make_unique<scene::RgbaImage>();
  {
    py::gil_scoped_release unlocked;
    try {
      args->tracks = app::expand_track_arguments(args->tracks);
      *image = app::render_picture(*args, diagnostics, std::move(more));
    } catch (const CLI::ParseError& e) {
      throw py::value_error(fmt::format("render(): {}", e.what()));
    }
  }
  const py::ssize_t h = image->height, w = image->width;
  std::uint8_t* pixels = image->rgba.data();
  py::capsule owner(image.release(), [](void* p) { delete static_cast<scene::RgbaImage*>(p); });
  py::array_t<std::uint8_t> picture({h, w, py::ssize_t{4}}, {w * 4, py::ssize_t{4}, py::ssize_t{1}}, pixels, owner);
  std::vector<std::string> warnings = diagnostics.warnings;
  for (const std::string& e : diagnostics.errors) warnings.push_back(e);
  return py::make_tuple(picture, texts(warnings));
}

py::bytes png_of(const py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>& picture) {
  if (picture.ndim() != 3 || picture.shape(2) != 4)
    throw py::value_error("png() takes an (h, w, 4) uint8 array, as render() returns");
  scene::RgbaImage image;
  image.height = static_cast<std::uint32_t>(picture.shape(0));
  image.width = static_cast<std::uint32_t>(picture.shape(1));
  image.rgba.assign(picture.data(), picture.data() + picture.size());
  std::vector<unsigned char> png;
  {
    py::gil_scoped_release unlocked;
    png = scene::encode_srgb_png(image);
  }
  return py::bytes(reinterpret_cast<const char*>(png.data()), png.size());
}

}  // namespace

void bind_rendering(py::module_& m) {
  m.def("render", &render, py::arg("paths"), py::arg("objects"), py::arg("options"),
        "The renderer behind trailray.render: (picture, warnings).");
  m.def("png", &png_of, py::arg("picture"), "An (h, w, 4) uint8 sRGB picture as PNG bytes (with an sRGB chunk).");
}

}  // namespace trailray::python
