#include "app/options/photo_options.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <system_error>

#include <fmt/format.h>

#include "track/photos/exif_reader.hpp"
#include "track/photos/exif_time.hpp"

namespace trailray::app {
namespace fs = std::filesystem;

void add_photo_options(CLI::App& command, PhotoArgs& args) {
  command
      .add_option("--photos", args.paths,
                  "Photos (JPEG, HEIC) placed on the tracks by their EXIF: by GPS position when within 100 m of a "
                  "track, else by time. A file, or a folder of .jpg/.jpeg/.heic/.heif files. Repeatable")
      ->type_name("DIR|FILE")
      ->allow_extra_args(false);  // one path per --photos: the words after it are tracks
  command
      .add_option("--photo-tz", args.time_zone,
                  "The UTC offset of the photos' clock where their EXIF has none (OffsetTimeOriginal), e.g. +02:00")
      ->type_name("+HH:MM")
      ->check([](const std::string& text) -> std::string {
        return track::parse_utc_offset(text) ? std::string()
                                             : "a UTC offset like +02:00 or -05:30 (at most 14 hours) is expected";
      });
  command
      .add_option("--photo-time-offset", args.time_offset_s,
                  "Seconds added to every photo's time: a camera clock 2 minutes slow is 120, one fast -120")
      ->type_name("S")
      ->check(CLI::Range(-366.0 * 86400.0, 366.0 * 86400.0));
}

bool has_photo_extension(const std::string& name) {
  const std::size_t dot = name.rfind('.');
  if (dot == std::string::npos) return false;
  std::string ext = name.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == "jpg" || ext == "jpeg" || ext == "heic" || ext == "heif";
}

std::vector<std::string> expand_photo_arguments(const std::vector<std::string>& arguments) {
  std::vector<std::string> out;
  for (const std::string& argument : arguments) {
    std::error_code ec;
    const fs::file_status status = fs::status(argument, ec);
    if (ec || !fs::exists(status)) throw PhotoArgumentError(fmt::format("{}: no such photo or folder (--photos)", argument));
    if (!fs::is_directory(status)) {
      out.push_back(argument);
      continue;
    }
    std::vector<std::string> names;
    fs::directory_iterator it(argument, ec);
    if (ec) throw PhotoArgumentError(fmt::format("{}: cannot list the folder: {}", argument, ec.message()));
    for (const fs::directory_entry& entry : it) {
      const std::string name = entry.path().filename().string();
      std::error_code type_ec;
      if (name.front() != '.' && has_photo_extension(name) && entry.is_regular_file(type_ec)) names.push_back(name);
    }
    std::sort(names.begin(), names.end());
    for (const std::string& name : names)
      out.push_back(argument.back() == '/' ? argument + name : argument + "/" + name);
  }
  return out;
}

track::PhotoPlacementOptions photo_placement_options(const PhotoArgs& args) {
  track::PhotoPlacementOptions options;
  if (!args.time_zone.empty()) options.default_offset_s = track::parse_utc_offset(args.time_zone);
  options.clock_offset_s = args.time_offset_s;
  options.time_zone_hint = "give it with --photo-tz +HH:MM";
  return options;
}

std::vector<track::PhotoMetadata> read_photo_files(const std::vector<std::string>& files, scene::Diagnostics& diagnostics) {
  std::vector<track::PhotoMetadata> photos;
  photos.reserve(files.size());
  for (const std::string& file : files) {
    track::PhotoReadResult r = track::read_photo_file(file);
    for (const auto& w : r.warnings) diagnostics.warning(w.to_string());
    if (!r.ok()) {
      diagnostics.warning(r.error->to_string());
      continue;
    }
    photos.push_back(std::move(r.photo));
  }
  return photos;
}

std::vector<track::PlacedPhoto> read_and_place_photos(const PhotoArgs& args, const std::vector<const track::Track*>& tracks,
                                                      scene::Diagnostics& diagnostics) {
  if (!args.any()) return {};
  const std::vector<track::PhotoMetadata> photos = read_photo_files(expand_photo_arguments(args.paths), diagnostics);
  track::PhotoPlacement placement = track::place_photos(photos, tracks, photo_placement_options(args));
  for (const auto& w : placement.warnings) diagnostics.warning(w.to_string());
  for (const auto& u : placement.unplaced) diagnostics.warning(u.reason.to_string());
  diagnostics.note(fmt::format("photos: {} of {} placed on the tracks", placement.placed.size(), photos.size()));
  return std::move(placement.placed);
}

}  // namespace trailray::app
