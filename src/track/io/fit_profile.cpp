#include "track/io/fit_profile.hpp"

#include <array>
#include <string_view>

namespace trailray::track::fit {
namespace {

template <std::size_t N>
std::string name_or_number(const std::array<std::string_view, N>& names, std::uint64_t value) {
  if (value < N && !names[static_cast<std::size_t>(value)].empty())
    return std::string(names[static_cast<std::size_t>(value)]);
  return std::to_string(value);
}

}  // namespace

std::string sport_name(std::uint64_t sport) {
  static constexpr std::array<std::string_view, 49> kNames = {"generic",
                                                              "running",
                                                              "cycling",
                                                              "transition",
                                                              "fitness_equipment",
                                                              "swimming",
                                                              "basketball",
                                                              "soccer",
                                                              "tennis",
                                                              "american_football",
                                                              "training",
                                                              "walking",
                                                              "cross_country_skiing",
                                                              "alpine_skiing",
                                                              "snowboarding",
                                                              "rowing",
                                                              "mountaineering",
                                                              "hiking",
                                                              "multisport",
                                                              "paddling",
                                                              "flying",
                                                              "e_biking",
                                                              "motorcycling",
                                                              "boating",
                                                              "driving",
                                                              "golf",
                                                              "hang_gliding",
                                                              "horseback_riding",
                                                              "hunting",
                                                              "fishing",
                                                              "inline_skating",
                                                              "rock_climbing",
                                                              "sailing",
                                                              "ice_skating",
                                                              "sky_diving",
                                                              "snowshoeing",
                                                              "snowmobiling",
                                                              "stand_up_paddleboarding",
                                                              "surfing",
                                                              "wakeboarding",
                                                              "water_skiing",
                                                              "kayaking",
                                                              "rafting",
                                                              "windsurfing",
                                                              "kitesurfing",
                                                              "tactical",
                                                              "jumpmaster",
                                                              "boxing",
                                                              "floor_climbing"};
  return name_or_number(kNames, sport);
}

std::string course_point_type_name(std::uint64_t type) {
  static constexpr std::array<std::string_view, 26> kNames = {
      "generic",         "summit",         "valley",          "water",          "food",
      "danger",          "left",           "right",           "straight",       "first_aid",
      "fourth_category", "third_category", "second_category", "first_category", "hors_category",
      "sprint",          "left_fork",      "right_fork",      "middle_fork",    "slight_left",
      "sharp_left",      "slight_right",   "sharp_right",     "u_turn",         "segment_start",
      "segment_end"};
  return name_or_number(kNames, type);
}

std::string file_type_name(std::uint64_t type) {
  static constexpr std::array<std::string_view, 7> kNames = {"",         "device",  "settings", "sport",
                                                             "activity", "workout", "course"};
  return name_or_number(kNames, type);
}

std::string manufacturer_name(std::uint64_t manufacturer) {
  switch (manufacturer) {
    case 1:
      return "garmin";
    case 15:
      return "dynastream";
    case 23:
      return "suunto";
    case 32:
      return "wahoo_fitness";
    case 255:
      return "development";
    default:
      return std::to_string(manufacturer);
  }
}

}  // namespace trailray::track::fit
