// libFuzzer target for the OpenStreetMap places (--places): libosmium parses the XML, but the tag
// handling is ours. The first byte picks the way in; each must answer or refuse, never crash:
//   ele      parse_ele -> NaN, or a finite number of metres within +-12,000
//   tags     the bytes as NUL-separated tag values through classify_place and place_label ->
//            no kind without a name; a label that starts with the name's valid UTF-8
//   osm      the bytes as an .osm XML file through read_osm_places_from_memory -> a
//            std::runtime_error naming it, or places with a name, a kind, a location on the
//            Earth and an ele that is NaN or sane

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "track/places/osm_places_reader.hpp"
#include "track/places/place_tags.hpp"

namespace {

using namespace trailray::track::places;

void check(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "fuzz: contract violated: %s\n", what);
    std::abort();
  }
}

bool sane_ele(double ele) { return std::isnan(ele) || (std::isfinite(ele) && std::fabs(ele) <= 12000.0); }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
  switch (data[0] % 3) {
    case 0:
      check(sane_ele(parse_ele(text)), "parse_ele: NaN or within +-12000 m");
      break;
    case 1: {
      std::vector<std::string_view> v;
      std::string_view rest = text;
      for (int i = 0; i < 6; ++i) {
        const std::size_t cut = rest.find('\0');
        v.push_back(rest.substr(0, cut));
        rest = cut == std::string_view::npos ? std::string_view() : rest.substr(cut + 1);
      }
      const PlaceTags tags{v[0], v[1], v[2], v[3], v[4], v[5]};
      for (bool area : {false, true}) {
        const auto kind = classify_place(tags, area);
        check(!kind || !tags.name.empty(), "classify_place: no place without a name");
        if (!kind) continue;
        Place p;
        p.name = std::string(tags.name);
        p.kind = *kind;
        p.ele_m = parse_ele(rest);
        check(!place_label(p).empty(), "place_label: a named place has a label");
      }
      break;
    }
    default: {
      std::vector<Place> places;
      try {
        places = read_osm_places_from_memory(text, "osm", "fuzz.osm");
      } catch (const std::runtime_error& e) {
        check(std::string_view(e.what()).starts_with("fuzz.osm: "), "errors name the file");
        break;
      }
      for (const Place& p : places) {
        check(!p.name.empty(), "a place has a name");
        check(p.lat_deg >= -90.0 && p.lat_deg <= 90.0 && p.lon_deg >= -180.0 && p.lon_deg <= 180.0,
              "a place lies on the Earth");
        check(sane_ele(p.ele_m), "a place's ele is NaN or sane");
      }
      break;
    }
  }
  return 0;
}
