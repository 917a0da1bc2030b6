#pragma once
// Tests that need photos with known EXIF write it into copies of a shared JPEG made at test time
// (never into ../shared/data), with exiv2 as a photo tool would.

#include <exiv2/exiv2.hpp>

#include <filesystem>
#include <map>
#include <string>

namespace trailray::test {

// Copies `source` to `target`, then sets each key ("Exif.Photo.DateTimeOriginal") to its value
// (exiv2's text form: "43/1 28/1 2964/100" for rationals). `clear_first`: drop the copy's EXIF
// block before (so only the keys given are there; with no keys, a JPEG without EXIF).
inline void write_exif_copy(const std::filesystem::path& source, const std::filesystem::path& target,
                            const std::map<std::string, std::string>& values, bool clear_first = true) {
  std::filesystem::copy_file(source, target, std::filesystem::copy_options::overwrite_existing);
  std::filesystem::permissions(target, std::filesystem::perms::owner_write, std::filesystem::perm_options::add);
  auto image = Exiv2::ImageFactory::open(target.string());  // exiv2 0.27: a std::auto_ptr, named by auto (deprecated)
  image->readMetadata();
  Exiv2::ExifData exif = clear_first ? Exiv2::ExifData() : image->exifData();
  for (const auto& [key, value] : values) exif[key] = value;
  image->setExifData(exif);
  if (clear_first) image->clearXmpData();
  image->writeMetadata();
}

// "43/1 28/1 2964/100"-style degrees, minutes, seconds of |deg| (to 1e-6 second).
inline std::string exif_dms(double deg) {
  const double a = deg < 0 ? -deg : deg;
  const auto d = static_cast<long long>(a);
  const double rem_min = (a - static_cast<double>(d)) * 60.0;
  const auto m = static_cast<long long>(rem_min);
  const auto micro_s = static_cast<long long>((rem_min - static_cast<double>(m)) * 60.0 * 1e6 + 0.5);
  return std::to_string(d) + "/1 " + std::to_string(m) + "/1 " + std::to_string(micro_s) + "/1000000";
}

}  // namespace trailray::test
