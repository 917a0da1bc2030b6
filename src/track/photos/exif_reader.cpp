#include "track/photos/exif_reader.hpp"

#include <exiv2/exiv2.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <system_error>

#include <fmt/format.h>

#include "track/photos/exif_time.hpp"

namespace trailray::track {
namespace {

// exiv2 0.27 keeps global state (its log handler and level, the XMP toolkit, the BMFF switch) and
// is not safe to set up from two threads; its parsing shares tables too. One lock around it all:
// photos are few and small beside the tracks, and the files are read outside it.
std::mutex& exiv2_mutex() {
  static std::mutex m;
  return m;
}

// exiv2's own complaints about the photo being parsed (guarded by exiv2_mutex()).
std::vector<std::string>* g_exiv2_messages = nullptr;

void exiv2_log_handler(int level, const char* message) {
  if (level < Exiv2::LogMsg::warn || g_exiv2_messages == nullptr || message == nullptr) return;
  std::string text(message);
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ' || text.back() == '.')) text.pop_back();
  g_exiv2_messages->push_back(std::move(text));
}

void set_up_exiv2_once() {
  static std::once_flag once;
  std::call_once(once, [] {
    Exiv2::XmpParser::initialize();
    Exiv2::enableBMFF(true);  // HEIC/HEIF: off by default in exiv2 0.27
    // Instead of exiv2 writing to standard error, its messages become this photo's warnings.
    Exiv2::LogMsg::setHandler(exiv2_log_handler);
    Exiv2::LogMsg::setLevel(Exiv2::LogMsg::warn);
  });
}

const Exiv2::Exifdatum* find(const Exiv2::ExifData& exif, const char* key) {
  const auto it = exif.findKey(Exiv2::ExifKey(key));
  return it == exif.end() ? nullptr : &*it;
}

// The n-th rational of a value as a double; nullopt when missing, not a rational, or x/0.
std::optional<double> rational_at(const Exiv2::Value& v, long n) {
  if (n >= v.count()) return std::nullopt;
  double num = 0, den = 0;
  if (v.typeId() == Exiv2::unsignedRational) {
    const auto* r = dynamic_cast<const Exiv2::URationalValue*>(&v);
    if (r == nullptr || static_cast<std::size_t>(n) >= r->value_.size()) return std::nullopt;
    num = r->value_[static_cast<std::size_t>(n)].first;
    den = r->value_[static_cast<std::size_t>(n)].second;
  } else if (v.typeId() == Exiv2::signedRational) {
    const auto* r = dynamic_cast<const Exiv2::RationalValue*>(&v);
    if (r == nullptr || static_cast<std::size_t>(n) >= r->value_.size()) return std::nullopt;
    num = r->value_[static_cast<std::size_t>(n)].first;
    den = r->value_[static_cast<std::size_t>(n)].second;
  } else {
    return std::nullopt;
  }
  if (den == 0) return std::nullopt;
  return num / den;
}

// A text field: the string for ASCII values, else nullopt.
std::optional<std::string> text_of(const Exiv2::ExifData& exif, const char* key) {
  const Exiv2::Exifdatum* d = find(exif, key);
  if (d == nullptr) return std::nullopt;
  if (d->typeId() != Exiv2::asciiString) return std::nullopt;
  return d->toString();
}

// A reference letter (GPSLatitudeRef "N"/"S"): ASCII, or a byte value where a broken block gave
// the field another type.
char ref_letter(const Exiv2::ExifData& exif, const char* key) {
  const Exiv2::Exifdatum* d = find(exif, key);
  if (d == nullptr || d->count() < 1) return 0;
  if (d->typeId() == Exiv2::asciiString) {
    const std::string s = d->toString();
    return s.empty() ? 0 : s.front();
  }
  const long c = d->toLong(0);
  return c > 0 && c < 128 ? static_cast<char>(c) : 0;
}

class PhotoParse {
 public:
  PhotoParse(const Exiv2::ExifData& exif, PhotoMetadata& photo, WarningCollector& warnings)
      : exif_(exif), photo_(photo), warnings_(warnings) {}

  void run() {
    read_position();
    read_altitude();
    read_time();
    read_gps_time();
    if (const Exiv2::Exifdatum* o = find(exif_, "Exif.Image.Orientation"); o != nullptr && o->count() >= 1) {
      const long v = o->toLong(0);
      if (v >= 1 && v <= 8) photo_.orientation = static_cast<int>(v);
    }
  }

 private:
  void warn(const std::string& message) { warnings_.add_single({}, message); }

  // Degrees from 1 to 3 rationals (degrees, minutes, seconds); nullopt with a warning when broken.
  std::optional<double> degrees(const char* key, const char* name) {
    const Exiv2::Exifdatum* d = find(exif_, key);
    if (d == nullptr) return std::nullopt;
    const Exiv2::Value& v = d->value();
    if (v.count() < 1) {
      warn(fmt::format("{} is empty: no GPS position", name));
      return std::nullopt;
    }
    double deg = 0, scale = 1;
    for (long i = 0; i < std::min<long>(v.count(), 3); ++i, scale /= 60.0) {
      const std::optional<double> part = rational_at(v, i);
      if (!part || !std::isfinite(*part) || *part < 0) {
        warn(fmt::format("{} is not a valid angle ({}): no GPS position", name, d->toString()));
        return std::nullopt;
      }
      deg += *part * scale;
    }
    return deg;
  }

  void read_position() {
    const std::optional<double> lat = degrees("Exif.GPSInfo.GPSLatitude", "GPSLatitude");
    const std::optional<double> lon = degrees("Exif.GPSInfo.GPSLongitude", "GPSLongitude");
    if (!lat || !lon) {
      const bool has_lat = find(exif_, "Exif.GPSInfo.GPSLatitude") != nullptr;
      const bool has_lon = find(exif_, "Exif.GPSInfo.GPSLongitude") != nullptr;
      if (has_lat != has_lon) warn("a GPS latitude without a longitude (or the other way): no GPS position");
      return;
    }
    double la = *lat, lo = *lon;
    const char lat_ref = ref_letter(exif_, "Exif.GPSInfo.GPSLatitudeRef");
    const char lon_ref = ref_letter(exif_, "Exif.GPSInfo.GPSLongitudeRef");
    if (lat_ref == 'S' || lat_ref == 's') la = -la;
    if (lon_ref == 'W' || lon_ref == 'w') lo = -lo;
    if (lat_ref != 'N' && lat_ref != 'n' && lat_ref != 'S' && lat_ref != 's')
      warn("GPSLatitudeRef is missing or not N/S: the latitude read as north");
    if (lon_ref != 'E' && lon_ref != 'e' && lon_ref != 'W' && lon_ref != 'w')
      warn("GPSLongitudeRef is missing or not E/W: the longitude read as east");
    if (std::abs(la) > 90.0 || std::abs(lo) > 180.0) {
      warn(fmt::format("GPS position {:.6f}, {:.6f} is outside the Earth's range: no GPS position", la, lo));
      return;
    }
    if (la == 0.0 && lo == 0.0) {
      // What a camera without a fix writes into the block it fills anyway.
      warn("GPS position 0, 0 (a camera without a fix writes it): no GPS position");
      return;
    }
    photo_.lat_deg = la;
    photo_.lon_deg = lo;
  }

  void read_altitude() {
    const Exiv2::Exifdatum* d = find(exif_, "Exif.GPSInfo.GPSAltitude");
    if (d == nullptr) return;
    const std::optional<double> alt = rational_at(d->value(), 0);
    if (!alt || !std::isfinite(*alt)) {
      warn(fmt::format("GPSAltitude is not a number ({}): no altitude", d->toString()));
      return;
    }
    const Exiv2::Exifdatum* ref = find(exif_, "Exif.GPSInfo.GPSAltitudeRef");
    const bool below_sea_level = ref != nullptr && ref->count() >= 1 && ref->toLong(0) == 1;
    photo_.alt_m = below_sea_level ? -*alt : *alt;
  }

  // DateTimeOriginal (else DateTimeDigitized, the same moment for a camera) with its sub-seconds
  // and offset; Image.DateTime is when the file was last changed, never used.
  void read_time() {
    const char* fields[][3] = {
        {"Exif.Photo.DateTimeOriginal", "Exif.Photo.SubSecTimeOriginal", "Exif.Photo.OffsetTimeOriginal"},
        {"Exif.Photo.DateTimeDigitized", "Exif.Photo.SubSecTimeDigitized", "Exif.Photo.OffsetTimeDigitized"}};
    for (const auto& f : fields) {
      const Exiv2::Exifdatum* d = find(exif_, f[0]);
      if (d == nullptr) continue;
      const std::string name = std::string(f[0]).substr(std::string(f[0]).rfind('.') + 1);
      const std::string text = d->typeId() == Exiv2::asciiString ? d->toString() : std::string();
      const std::optional<ExifDateTime> t = parse_exif_datetime(text);
      if (!t) {
        warn(text.find_first_not_of(std::string(" :\0", 3)) == std::string::npos
                 ? fmt::format("{} is empty: no time", name)
                 : fmt::format("{} '{}' is not a date and time: no time", name, text));
        continue;
      }
      photo_.taken_local_s = t->local_s;
      if (!t->has_fraction) {
        if (const auto sub = text_of(exif_, f[1]))
          if (const auto fraction = parse_exif_subseconds(*sub)) photo_.taken_local_s += *fraction;
      }
      photo_.offset_s = t->offset_s;
      if (const auto offset_text = text_of(exif_, f[2]); offset_text && !offset_text->empty()) {
        if (const auto offset = parse_utc_offset(*offset_text))
          photo_.offset_s = offset;
        else if (offset_text->find_first_not_of(std::string(" :\0", 3)) != std::string::npos)
          warn(fmt::format("{} '{}' is not a UTC offset: ignored", std::string(f[2]).substr(11), *offset_text));
      }
      return;
    }
  }

  void read_gps_time() {
    const auto date = text_of(exif_, "Exif.GPSInfo.GPSDateStamp");
    const Exiv2::Exifdatum* stamp = find(exif_, "Exif.GPSInfo.GPSTimeStamp");
    if (!date || stamp == nullptr) return;
    const std::optional<ExifDateTime> day = parse_exif_datetime(date->substr(0, 10) + " 00:00:00");
    const std::optional<double> h = rational_at(stamp->value(), 0), m = rational_at(stamp->value(), 1),
                                s = rational_at(stamp->value(), 2);
    if (!day || !h || !m || !s) return;  // only a hint: nothing to warn about
    const double t = day->local_s + *h * 3600.0 + *m * 60.0 + *s;
    if (std::isfinite(t) && *h >= 0 && *h < 24 && *m >= 0 && *m < 60 && *s >= 0 && *s <= 61) photo_.gps_time_utc_s = t;
  }

  const Exiv2::ExifData& exif_;
  PhotoMetadata& photo_;
  WarningCollector& warnings_;
};

bool is_photo_type(int type) { return type == Exiv2::ImageType::jpeg || type == Exiv2::ImageType::bmff; }

// What the first bytes say, before exiv2 sees them: only JPEG and ISO BMFF (HEIC, HEIF) go on, so
// exiv2's other parsers (and their bugs) are never reached from a photo argument.
enum class Magic { jpeg, bmff, other_image, none };
Magic magic_of(const std::uint8_t* d, std::size_t n) {
  auto starts = [&](const char* m, std::size_t len, std::size_t at = 0) {
    return n >= at + len && std::equal(d + at, d + at + len, reinterpret_cast<const std::uint8_t*>(m));
  };
  if (starts("\xFF\xD8\xFF", 3)) return Magic::jpeg;
  if (starts("ftyp", 4, 4)) return Magic::bmff;
  if (starts("\x89PNG", 4) || starts("GIF8", 4) || starts("II*\0", 4) || starts("MM\0*", 4) || starts("BM", 2) ||
      (starts("RIFF", 4) && starts("WEBP", 4, 8)))
    return Magic::other_image;
  return Magic::none;
}

std::string size_text(std::int64_t bytes) {
  return bytes >= (std::int64_t{1} << 20) ? fmt::format("{:.0f} MiB", static_cast<double>(bytes) / (1 << 20))
                                          : fmt::format("{} bytes", bytes);
}

}  // namespace

PhotoReadResult read_photo_bytes(const std::uint8_t* data, std::size_t size, const std::string& display_name,
                                 const PhotoReadOptions& options) {
  PhotoReadResult result;
  result.photo.path = display_name;
  auto fail = [&](const std::string& message) {
    result.error = Diagnostic{display_name, {}, message};
    return result;
  };
  if (static_cast<std::int64_t>(size) > options.max_bytes)
    return fail(fmt::format("the photo is {}, over the {} a photo may have: skipped", size_text(static_cast<std::int64_t>(size)),
                            size_text(options.max_bytes)));
  if (size == 0) return fail("the file is empty, not a photo");
  switch (magic_of(data, size)) {
    case Magic::none:
      return fail("not an image (JPEG or HEIC expected)");
    case Magic::other_image:
      return fail("an image, but not JPEG or HEIC: photos are read from those only");
    default:
      break;
  }
  WarningCollector warnings(display_name);
  std::vector<std::string> messages;
  {
    const std::lock_guard<std::mutex> lock(exiv2_mutex());
    set_up_exiv2_once();
    g_exiv2_messages = &messages;
    struct Unhook {
      ~Unhook() { g_exiv2_messages = nullptr; }
    } unhook;
    try {
      const auto* bytes = reinterpret_cast<const Exiv2::byte*>(data);
      const long length = static_cast<long>(size);
      const int type = Exiv2::ImageFactory::getType(bytes, length);
      if (type == Exiv2::ImageType::none) return fail("not an image (JPEG or HEIC expected)");
      if (!is_photo_type(type)) return fail("an image, but not JPEG or HEIC: photos are read from those only");
      auto image = Exiv2::ImageFactory::open(bytes, length);  // exiv2 0.27: a std::auto_ptr, named by auto (deprecated)
      if (image.get() == nullptr) return fail("not an image (JPEG or HEIC expected)");
      image->readMetadata();
      const Exiv2::ExifData& exif = image->exifData();
      result.photo.has_exif = !exif.empty();
      PhotoParse(exif, result.photo, warnings).run();
      result.photo.width = image->pixelWidth() > 0 ? image->pixelWidth() : 0;
      result.photo.height = image->pixelHeight() > 0 ? image->pixelHeight() : 0;
      if (result.photo.width == 0 || result.photo.height == 0) {
        const Exiv2::Exifdatum* w = find(exif, "Exif.Photo.PixelXDimension");
        const Exiv2::Exifdatum* h = find(exif, "Exif.Photo.PixelYDimension");
        if (w != nullptr && h != nullptr && w->count() >= 1 && h->count() >= 1 && w->toLong(0) > 0 && h->toLong(0) > 0 &&
            w->toLong(0) <= 1000000 && h->toLong(0) <= 1000000) {
          result.photo.width = static_cast<int>(w->toLong(0));
          result.photo.height = static_cast<int>(h->toLong(0));
        }
      }
    } catch (const std::exception& e) {
      // exiv2 0.27 throws Exiv2::AnyError (a std::exception) for what it cannot parse.
      result.photo = PhotoMetadata{};
      result.photo.path = display_name;
      return fail(fmt::format("its EXIF block cannot be read: {}", e.what()));
    } catch (...) {
      result.photo = PhotoMetadata{};
      result.photo.path = display_name;
      return fail("its EXIF block cannot be read");
    }
  }
  for (const std::string& m : messages) {
    // XMP is not read (everything placed comes from EXIF), so its complaints say nothing useful.
    if (m.find("XMP") != std::string::npos) continue;
    warnings.add("exiv2", {}, "EXIF block: " + m);
  }
  result.warnings = warnings.diagnostics();
  return result;
}

PhotoReadResult read_photo_file(const std::string& path, const PhotoReadOptions& options) {
  PhotoReadResult result;
  result.photo.path = path;
  auto fail = [&](const std::string& message) {
    result.error = Diagnostic{path, {}, message};
    return result;
  };
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status)) return fail("no such file");
  if (!std::filesystem::is_regular_file(status)) return fail("not a file");
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) return fail(fmt::format("cannot read its size: {}", ec.message()));
  if (static_cast<std::int64_t>(size) > options.max_bytes)
    return fail(fmt::format("the photo is {}, over the {} a photo may have: skipped", size_text(static_cast<std::int64_t>(size)),
                            size_text(options.max_bytes)));
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(size));
  std::ifstream in(path, std::ios::binary);
  if (!in) return fail("cannot be opened");
  in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  if (in.gcount() != static_cast<std::streamsize>(bytes.size())) return fail("cannot be read (shorter than its size)");
  return read_photo_bytes(bytes.data(), bytes.size(), path, options);
}

}  // namespace trailray::track
