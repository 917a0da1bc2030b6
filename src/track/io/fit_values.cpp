// FIT field values: base types, their invalid values, byte order; and the FIT CRC.
#include <cmath>
#include <cstring>

#include "track/io/fit_decoder.hpp"

namespace trailray::track::fit {
namespace {

// Base type numbers (the low five bits of the base type byte).
enum BaseType : std::uint8_t {
  kEnum = 0x00,
  kSint8 = 0x01,
  kUint8 = 0x02,
  kSint16 = 0x03,
  kUint16 = 0x04,
  kSint32 = 0x05,
  kUint32 = 0x06,
  kString = 0x07,
  kFloat32 = 0x08,
  kFloat64 = 0x09,
  kUint8z = 0x0A,
  kUint16z = 0x0B,
  kUint32z = 0x0C,
  kByte = 0x0D,
  kSint64 = 0x0E,
  kUint64 = 0x0F,
  kUint64z = 0x10,
};

std::uint64_t load_unsigned(std::string_view bytes, std::size_t size, bool big_endian) {
  std::uint64_t v = 0;
  for (std::size_t i = 0; i < size; ++i) {
    const auto b = static_cast<std::uint8_t>(bytes[big_endian ? i : size - 1 - i]);
    v = (v << 8) | b;
  }
  return v;
}

// The first element of `f`, or nullopt when its size is no whole number of elements (the
// field is then only bytes: the coros file has such fields).
std::optional<std::uint64_t> first_element(const Field& f, bool big_endian, std::size_t& size) {
  size = base_type_size(f.base_type);
  if (size == 0 || f.bytes.size() < size || f.bytes.size() % size != 0) return std::nullopt;
  return load_unsigned(f.bytes, size, big_endian);
}

std::int64_t sign_extend(std::uint64_t v, std::size_t size) {
  const unsigned bits = static_cast<unsigned>(size * 8);
  if (bits >= 64) return static_cast<std::int64_t>(v);
  const std::uint64_t sign = std::uint64_t{1} << (bits - 1);
  return static_cast<std::int64_t>((v ^ sign) - sign);
}

}  // namespace

std::size_t base_type_size(std::uint8_t base_type) {
  switch (base_type & 0x1F) {
    case kEnum:
    case kSint8:
    case kUint8:
    case kString:
    case kUint8z:
    case kByte:
      return 1;
    case kSint16:
    case kUint16:
    case kUint16z:
      return 2;
    case kSint32:
    case kUint32:
    case kFloat32:
    case kUint32z:
      return 4;
    case kFloat64:
    case kSint64:
    case kUint64:
    case kUint64z:
      return 8;
    default:
      return 0;
  }
}

const Field* Message::find(std::uint8_t number) const {
  for (const Field& f : fields)
    if (f.number == number) return &f;
  return nullptr;
}

std::optional<std::int64_t> Message::integer(std::uint8_t number) const {
  const Field* f = find(number);
  if (!f) return std::nullopt;
  std::size_t size = 0;
  auto raw = first_element(*f, big_endian, size);
  if (!raw) return std::nullopt;
  const std::uint64_t all_ones = size >= 8 ? ~std::uint64_t{0} : (std::uint64_t{1} << (size * 8)) - 1;
  switch (f->base_type & 0x1F) {
    case kEnum:
    case kUint8:
    case kUint16:
    case kUint32:
    case kByte:
      if (*raw == all_ones) return std::nullopt;
      return static_cast<std::int64_t>(*raw);
    case kUint64:
      if (*raw == all_ones || *raw > static_cast<std::uint64_t>(INT64_MAX)) return std::nullopt;
      return static_cast<std::int64_t>(*raw);
    case kUint8z:
    case kUint16z:
    case kUint32z:
    case kUint64z:
      if (*raw == 0 || *raw > static_cast<std::uint64_t>(INT64_MAX)) return std::nullopt;
      return static_cast<std::int64_t>(*raw);
    case kSint8:
    case kSint16:
    case kSint32:
    case kSint64:
      if (*raw == all_ones >> 1) return std::nullopt;  // 0x7F, 0x7FFF, ...
      return sign_extend(*raw, size);
    default:
      return std::nullopt;  // strings, floats, unknown types
  }
}

std::optional<double> Message::number(std::uint8_t number) const {
  const Field* f = find(number);
  if (!f) return std::nullopt;
  const std::uint8_t type = f->base_type & 0x1F;
  if (type != kFloat32 && type != kFloat64) {
    auto v = integer(number);
    if (!v) return std::nullopt;
    return static_cast<double>(*v);
  }
  std::size_t size = 0;
  auto raw = first_element(*f, big_endian, size);
  if (!raw) return std::nullopt;
  double v = 0.0;
  if (type == kFloat32) {
    if (*raw == 0xFFFFFFFFu) return std::nullopt;
    const auto bits = static_cast<std::uint32_t>(*raw);
    float fv = 0.0f;
    std::memcpy(&fv, &bits, sizeof fv);
    v = fv;
  } else {
    if (*raw == ~std::uint64_t{0}) return std::nullopt;
    std::memcpy(&v, &*raw, sizeof v);
  }
  if (!std::isfinite(v)) return std::nullopt;
  return v;
}

std::string Message::text(std::uint8_t number) const {
  const Field* f = find(number);
  if (!f || (f->base_type & 0x1F) != kString) return {};
  std::string_view s = f->bytes;
  if (auto nul = s.find('\0'); nul != std::string_view::npos) s = s.substr(0, nul);
  return std::string(s);
}

std::uint16_t crc16(std::string_view bytes, std::uint16_t crc) {
  static constexpr std::uint16_t kTable[16] = {0x0000, 0xCC01, 0xD801, 0x1400, 0xF001, 0x3C00, 0x2800, 0xE401,
                                               0xA001, 0x6C00, 0x7800, 0xB401, 0x5000, 0x9C01, 0x8801, 0x4400};
  for (char c : bytes) {
    const auto b = static_cast<std::uint8_t>(c);
    std::uint16_t t = kTable[crc & 0xF];
    crc = static_cast<std::uint16_t>(((crc >> 4) & 0x0FFF) ^ t ^ kTable[b & 0xF]);
    t = kTable[crc & 0xF];
    crc = static_cast<std::uint16_t>(((crc >> 4) & 0x0FFF) ^ t ^ kTable[(b >> 4) & 0xF]);
  }
  return crc;
}

}  // namespace trailray::track::fit
